/* noise.c: POV-Ray's solid noise and turbulence (see pattern.h).
 *
 * Generators 1 and 2 are one lattice noise. Each integer lattice point gets
 * a record from its hash (noise_table.c): a value in [0, 1] and a gradient.
 * Inside a cell the eight corners' linear functions value + gradient·(p − corner)
 * are blended with the cubic weights s(t) = t²(3 − 2t) per axis. The lattice
 * coordinates are offset by NOISE_OFFSET before hashing, as POV-Ray does, so
 * that negative coordinates need no special case; the hash repeats every 4096
 * units. Generator 1 clips the sum to [0, 1]; generator 2 maps the sum's full
 * range [−0.55242, 1.48898] linearly onto [0, 1] (its values stay within about
 * [0.06, 0.93]). The vector noise blends the same corners with the record
 * shifted by 0, 4 and 8 for x, y and z and is centred on 0.
 *
 * Generator 3 is a gradient noise: each corner contributes gradient·(p −
 * corner) only, on a lattice shifted by GEN3_SHIFT, scaled and centred on
 * 0.4925 as POV-Ray's is (measured); its gradients are unit vectors of our
 * own choosing, so its values have POV-Ray's character but not its digits. */
#include "pattern/pattern.h"
#include "pattern/noise_table.h"

#include <math.h>

#define NOISE_OFFSET 10000      /* ≡ 1808 (mod 4096), what POV-Ray adds */
#define HASH_MASK (NOISE_HASH_SIZE - 1)

/* Generator 2's linear map of the raw sum onto [0, 1]. */
#define GEN2_SHIFT 0.55242
#define GEN2_SCALE 0.48985582

/* Generator 3: the lattice offset, centre and gradient length (measured). */
#define GEN3_SHIFT 0.0231572128
#define GEN3_CENTRE 0.4925
#define GEN3_GRAD 0.795

static inline double scurve(double t)
{
	return t * t * (3.0 - 2.0 * t);
}

static inline int hash3(int x, int y, int z)
{
	return noise_hash[noise_hash[noise_hash[x & HASH_MASK] ^ (y & HASH_MASK)] ^ (z & HASH_MASK)];
}

/* The lattice cell of p: integer corner (offset for hashing), fraction,
 * and the blend weights. Coordinates beyond ±2^30 wrap into range rather
 * than overflow. */
struct cell {
	int ix, iy, iz;
	double fx, fy, fz;
	double sx, sy, sz;
};

static inline int lattice(double v, double *frac)
{
	double f = floor(v);
	*frac = v - f;
	f = fmod(f, 1073741824.0);
	return (int)f + NOISE_OFFSET;
}

static inline void cell_of(vec3 p, struct cell *c)
{
	c->ix = lattice(p.x, &c->fx);
	c->iy = lattice(p.y, &c->fy);
	c->iz = lattice(p.z, &c->fz);
	c->sx = scurve(c->fx);
	c->sy = scurve(c->fy);
	c->sz = scurve(c->fz);
}

/* Σ over the corners of weight × (0.5·t[h+k] + gradient(h+k)·d), with k the
 * record shift (0, 4 or 8). The scalar noise is this (k = 0) plus 0.5. */
static double blend(const struct cell *c, int k)
{
	double sum = 0;
	for (int corner = 0; corner < 8; corner++) {
		int cx = corner & 1, cy = (corner >> 1) & 1, cz = corner >> 2;
		double w = (cx ? c->sx : 1 - c->sx) * (cy ? c->sy : 1 - c->sy) * (cz ? c->sz : 1 - c->sz);
		const double *r = &noise_rtable[(hash3(c->ix + cx, c->iy + cy, c->iz + cz) & 0xFF) + k];
		double dx = c->fx - cx, dy = c->fy - cy, dz = c->fz - cz;
		sum += w * (0.5 * r[0] + r[1] * dx + r[2] * dy + r[3] * dz);
	}
	return sum;
}

/* Generator 3's unit gradient at a corner, from its hash (our own table:
 * the record's gradient direction). */
static vec3 gen3_gradient(int h)
{
	const double *r = &noise_rtable[h & 0xFF];
	vec3 g = v3(r[1], r[2], r[3]);
	double l = v3_len(g);
	return l > 1e-6 ? v3_scale(g, 1.0 / l) : v3(1, 0, 0);
}

/* Generator 3's gradient sum at p for record shift k (0, 4, 8: the vector
 * noise's components use differently hashed corners). */
static double gradient_sum(vec3 p, int k)
{
	struct cell c;
	cell_of(v3_add(p, v3(GEN3_SHIFT, GEN3_SHIFT, GEN3_SHIFT)), &c);
	double sum = 0;
	for (int corner = 0; corner < 8; corner++) {
		int cx = corner & 1, cy = (corner >> 1) & 1, cz = corner >> 2;
		double w = (cx ? c.sx : 1 - c.sx) * (cy ? c.sy : 1 - c.sy) * (cz ? c.sz : 1 - c.sz);
		int h = hash3((c.ix + cx) & 2047, (c.iy + cy) & 2047, (c.iz + cz) & 2047) + k * 17;
		vec3 g = gen3_gradient(h);
		sum += w * (g.x * (c.fx - cx) + g.y * (c.fy - cy) + g.z * (c.fz - cz));
	}
	return GEN3_GRAD * sum;
}

static inline double clamp01(double v)
{
	return v < 0 ? 0 : v > 1 ? 1 : v;
}

double noise3(vec3 p, int generator)
{
	if (generator == 3)
		return clamp01(GEN3_CENTRE + gradient_sum(p, 0));
	struct cell c;
	cell_of(p, &c);
	double raw = blend(&c, 0) + 0.5;
	if (generator == 1)
		return clamp01(raw);
	return clamp01((raw + GEN2_SHIFT) * GEN2_SCALE);
}

vec3 dnoise3(vec3 p, int generator)
{
	if (generator == 3)
		return v3(gradient_sum(p, 0) * 2, gradient_sum(p, 4) * 2, gradient_sum(p, 8) * 2);
	struct cell c;
	cell_of(p, &c);
	return v3(blend(&c, 0), blend(&c, 4), blend(&c, 8));
}

/* The scalar turbulence: Σ over the octaves of (noise − 0.25) × omega^i at
 * p × lambda^i, the first octave's noise clipped to [0.25, 0.75] (measured:
 * POV-Ray's marble); with generator 1, of noise / 2 (measured the same
 * way, also where the noise clamps at 0 and 1, in the first octave and
 * the second). POV-Ray keeps omega and lambda in single precision. */
double turbulence1(vec3 p, const struct turbulence *t, int generator)
{
	double omega = (float)t->omega, lambda = (float)t->lambda;
	double sum = 0, amp = 1, freq = 1;
	for (int i = 0; i < t->octaves; i++) {
		double n = noise3(v3_scale(p, freq), generator);
		if (generator == 1)
			n = 0.5 * n + 0.25;
		else if (i == 0)
			n = n < 0.25 ? 0.25 : n > 0.75 ? 0.75 : n;
		sum += amp * (n - 0.25);
		amp *= omega;
		freq *= lambda;
	}
	return sum;
}

/* The vector turbulence: Σ over the octaves of dnoise × omega^i at
 * p × lambda^i (measured: warp { turbulence }). */
vec3 turbulence3(vec3 p, const struct turbulence *t, int generator)
{
	double omega = (float)t->omega, lambda = (float)t->lambda;
	vec3 sum = v3(0, 0, 0);
	double amp = 1, freq = 1;
	for (int i = 0; i < t->octaves; i++) {
		sum = v3_madd(sum, dnoise3(v3_scale(p, freq), generator), amp);
		amp *= omega;
		freq *= lambda;
	}
	return sum;
}

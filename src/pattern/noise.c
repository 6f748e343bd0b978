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
 * Generator 3 is Perlin's gradient noise as POV-Ray has it: each corner
 * contributes gradient·(p − corner) only, on a lattice shifted by
 * GEN3_SHIFT, centred on 0.4925; the gradients (length 0.795) and Perlin's
 * additive corner hash, period 2048, were measured (noise3_gen.py) and give
 * POV-Ray's values to 2e-9. The vector noise (turbulence) does not depend
 * on the generator: POV-Ray's is generator 2's whatever the pattern says. */
#include "pattern/pattern.h"
#include "pattern/noise_table.h"

#include <limits.h>
#include <math.h>

#define NOISE_OFFSET 10000      /* ≡ 1808 (mod 4096), what POV-Ray adds */
#define HASH_MASK (NOISE_HASH_SIZE - 1)

/* Generator 2's linear map of the raw sum onto [0, 1]. */
#define GEN2_SHIFT 0.55242
#define GEN2_SCALE 0.48985582

/* Generator 3: the lattice offset and centre (measured). */
#define GEN3_SHIFT 0.0231572128
#define GEN3_CENTRE 0.4925

static inline double scurve(double t)
{
	return t * t * (3.0 - 2.0 * t);
}

static inline int hash3(int x, int y, int z)
{
	return noise_hash[noise_hash[noise_hash[x & HASH_MASK] ^ (y & HASH_MASK)] ^ (z & HASH_MASK)];
}

/* The lattice cell of p: integer corner (offset for hashing), fraction,
 * and the blend weights. */
struct cell {
	int ix, iy, iz;
	double fx, fy, fz;
	double sx, sy, sz;
};

static inline int lattice(double v, double *frac)
{
	/* Beyond the range of a 32-bit int POV-Ray's corner becomes INT_MIN
	 * (what x86 makes of an int conversion out of range) and the fraction
	 * v - INT_MIN, far outside [0, 1], so that the noise saturates at 0 or 1
	 * (measured: bozo at 96 points out to 1e11 and at +-2^31 + d, all equal
	 * to POV-Ray's; the fog of a ray that misses everything shows it). The
	 * offset then wraps as a 32-bit int would. */
	double f = floor(v);
	int i = f >= -2147483648.0 && f < 2147483648.0 ? (int)f : INT_MIN;
	*frac = v - (double)i;
	return (int)((unsigned)i + NOISE_OFFSET);
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

/* Generator 3's lattice coordinate of v (shifted), its fraction into
 * *frac, wrapped into [0, 2048). POV-Ray adds 1.5 * 2^23 with the shift,
 * which leaves the fraction 29 bits for either sign of v (measured: values
 * along lines fit this to 1e-16, and the plain fraction only to 5e-10). */
static inline int lattice3(double v, double *frac)
{
	double q = v + (12582912.0 + GEN3_SHIFT);
	double f = floor(q);
	*frac = q - f;
	f = fmod(f, (double)NOISE3_SIZE);
	if (f < 0)
		f += NOISE3_SIZE;
	return f >= 0 && f < NOISE3_SIZE ? (int)f : 0; /* NaN at an infinite v */
}

/* Generator 3's noise at p. */
static double gradient_noise(vec3 p)
{
	const int m = NOISE3_SIZE - 1;
	double fx, fy, fz;
	int ix = lattice3(p.x, &fx), iy = lattice3(p.y, &fy), iz = lattice3(p.z, &fz);
	double sx = scurve(fx), sy = scurve(fy), sz = scurve(fz);
	double sum = 0;
	for (int cx = 0; cx < 2; cx++) {
		int hx = noise3_hash[(ix + cx + NOISE3_X0) & m];
		double wx = cx ? sx : 1 - sx;
		for (int cy = 0; cy < 2; cy++) {
			int hy = noise3_hash[(hx + iy + cy) & m];
			double wxy = wx * (cy ? sy : 1 - sy);
			for (int cz = 0; cz < 2; cz++) {
				const double *g = noise3_grad[(hy + iz + cz) & m];
				double w = wxy * (cz ? sz : 1 - sz);
				sum += w * (g[0] * (fx - cx) + g[1] * (fy - cy) + g[2] * (fz - cz));
			}
		}
	}
	return sum;
}

static inline double clamp01(double v)
{
	return v < 0 ? 0 : v > 1 ? 1 : v;
}

double noise3(vec3 p, int generator)
{
	if (generator == 3)
		return clamp01(GEN3_CENTRE + gradient_noise(p));
	struct cell c;
	cell_of(p, &c);
	double raw = blend(&c, 0) + 0.5;
	if (generator == 1)
		return clamp01(raw);
	return clamp01((raw + GEN2_SHIFT) * GEN2_SCALE);
}

vec3 dnoise3(vec3 p, int generator)
{
	(void)generator;   /* measured: the same for generators 1, 2 and 3 */
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

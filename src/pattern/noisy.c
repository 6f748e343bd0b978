/* noisy.c: the noise-based patterns (see kinds.h) and the special normal
 * perturbations of bumps, dents, ripples, waves, wrinkles and facets.
 *
 * Values measured against POV-Ray 3.7 with `function { pattern { K } }`:
 * bozo, spotted, bumps, dents, granite, wrinkles, marble, wood, agate,
 * ripples, waves, and their turbulence (generators 1, 2 and 3) agree with
 * it to 1e-10; so do cells and crackle, from POV-Ray's cell random numbers
 * (cell_table.h). The normals of bumps, dents, wrinkles, ripples, waves
 * and facets were measured from renders (kinds.h; facets: the normal solved
 * per pixel from lights along the axes) and agree to 3e-5 (facets to 8e-6,
 * the renders' resolution). */
#include "pattern/kinds.h"
#include "pattern/cell_table.h"
#include "pattern/noise_table.h"

#include <math.h>
#include <stdlib.h>

/* The generator a pattern uses: its own, else the scene's, else 2. */
static int gen_of(const struct pattern *pt, const struct pattern_ctx *ctx)
{
	if (pt->noise_generator)
		return pt->noise_generator;
	return ctx && ctx->noise_generator ? ctx->noise_generator : 2;
}

/* The noise as POV-Ray's granite and wrinkles use it, in [0, 1]: with
 * generator 1 the noise itself, with 2 and 3 twice the noise less 0.5,
 * clipped (measured: granite and wrinkles with generator 2 are exact with
 * this; with generator 1 they are exact with the noise as it is, where the
 * generator-2 form would be about twice as large). */
static double turb_noise(vec3 p, int gen)
{
	double n = noise3(p, gen);
	if (gen == 1)
		return n;
	n = 2 * n - 0.5;
	return n < 0 ? 0 : n > 1 ? 1 : n;
}

/* The classic turbulence marble adds to its value: 2 × amount.x ×
 * turbulence1 (measured). */
static double value_turbulence(const struct pattern *pt, vec3 q, int gen)
{
	if (!pt->has_turbulence)
		return 0;
	return 2.0 * pt->turb.amount.x * turbulence1(q, &pt->turb, gen);
}

PATTERN_FN(bozo)
{
	return noise3(q, gen_of(pt, ctx));
}

PATTERN_FN(spotted)
{
	return noise3(q, gen_of(pt, ctx));
}

PATTERN_FN(bumps)
{
	return noise3(q, gen_of(pt, ctx));
}

PATTERN_FN(dents)
{
	double n = noise3(q, gen_of(pt, ctx));
	return n * n * n;
}

/* granite: 6 octaves of |turb_noise − 0.5| / 2^i at 4 × 2^i × q. */
PATTERN_FN(granite)
{
	int gen = gen_of(pt, ctx);
	double sum = 0, freq = 4;
	for (int i = 0; i < 6; i++, freq *= 2)
		sum += fabs(turb_noise(v3_scale(q, freq), gen) - 0.5) * 4 / freq;
	return sum;
}

/* wrinkles: 10 octaves of turb_noise / 2 / 2^i at 2^i × q. */
PATTERN_FN(wrinkles)
{
	int gen = gen_of(pt, ctx);
	double sum = 0, freq = 1;
	for (int i = 0; i < 10; i++, freq *= 2)
		sum += 0.5 * turb_noise(v3_scale(q, freq), gen) / freq;
	return sum;
}

PATTERN_FN(marble)
{
	return q.x + value_turbulence(pt, q, gen_of(pt, ctx));
}

/* wood: the distance from the z axis. Its turbulence is its own
 * (measured to 1e-13): with D the vector turbulence at q (the pattern's
 * octaves, omega and lambda, not its amount; the same for every
 * generator, as all vector noise) and T the amount, x moves by
 * sin(2 pi T.x (x + D.x)) and y by sin(2 pi T.y (y + D.y)). */
PATTERN_FN(wood)
{
	double x = q.x, y = q.y;
	if (pt->has_turbulence) {
		vec3 d = turbulence3(q, &pt->turb, gen_of(pt, ctx));
		x += sin(2 * M_PI * pt->turb.amount.x * (q.x + d.x));
		y += sin(2 * M_PI * pt->turb.amount.y * (q.y + d.y));
	}
	return sqrt(x * x + y * y);
}

/* agate: ((1 + sin(2π × 1.1 × u)) / 2)^0.77 with u = z + 26/11 ×
 * agate_turb × the scalar turbulence at q, with the pattern's octaves,
 * omega and lambda (default 6, 0.5, 2). Measured: with a small agate_turb
 * the phase moves by exactly 26/11 (to 1e-6) times the turbulence, for
 * generators 1 and 2 and other octaves, omega and lambda; `turbulence`
 * moves the point (POV-Ray gives the same values as with warp { turbulence }). */
PATTERN_FN(agate)
{
	double agate_turb = (float)pt->f[0];          /* single precision in POV-Ray (measured) */
	double u = q.z + agate_turb * (26.0 / 11.0) * turbulence1(q, &pt->turb, gen_of(pt, ctx));
	double s = (1.0 + sin(2 * M_PI * 1.1 * u)) * 0.5;
	return pow(s < 0 ? 0 : s, 0.77);
}

/* ---- wave sources (ripples, waves) ----
 * POV-Ray's wave sources: source i is a unit vector w_i and a frequency
 * f_i (only waves uses it); both the value and the normal measure the
 * distance from the pattern-space point to w_i. Measured from POV-Ray 3.7
 * renders with global_settings { number_of_waves K } for K = 1, 2, ...:
 * each K adds one source and keeps the others, so they were fitted one at
 * a time (ripples at two heights for the centre, waves for the frequency;
 * the orthographic camera looking straight down that was used shows the
 * image mirrored in x in POV-Ray, which the fits allowed for). The first
 * ten were then refined against function { pattern { ripples } } and
 * { waves } as POV-Ray prints them while parsing (the same sources), to
 * 1e-15 (wave_sources.inc). */

static const struct wave_source {
	vec3 w;
	double f;
} wave_sources[] = {
#include "pattern/wave_sources.inc"
};

#define MAX_WAVES ((int)(sizeof wave_sources / sizeof wave_sources[0]))

static int wave_count(const struct pattern_ctx *ctx)
{
	int n = ctx && ctx->number_of_waves > 0 ? ctx->number_of_waves : 10;
	return n > MAX_WAVES ? MAX_WAVES : n;
}

/* ripples and waves use the pattern's frequency F and phase P inside the
 * sine, and then (like every pattern) on the value too (measured; both in
 * single precision, as POV-Ray keeps them). */

/* ripples: the mean over the sources of 0.5 + 0.5 sin(2π (F d + P)). */
PATTERN_FN(ripples)
{
	int n = wave_count(ctx);
	double sum = 0, F = (float)pt->frequency, P = (float)pt->phase;
	for (int i = 0; i < n; i++)
		sum += 0.5 + 0.5 * sin(2 * M_PI * (F * v3_len(v3_sub(q, wave_sources[i].w)) + P));
	return sum / n;
}

/* waves: 0.5 plus the mean over the sources of
 * 0.2 sin(2π (f F d + P)) / f. */
PATTERN_FN(waves)
{
	int n = wave_count(ctx);
	double sum = 0, F = (float)pt->frequency, P = (float)pt->phase;
	for (int i = 0; i < n; i++) {
		double f = wave_sources[i].f;
		sum += 0.2 * sin(2 * M_PI * (f * F * v3_len(v3_sub(q, wave_sources[i].w)) + P)) / f;
	}
	return 0.5 + sum / n;
}

/* ---- cells, crackle ---- */

/* The lattice hash of unit cube (i, j, k) (integral values), as POV-Ray's
 * cells and crackle take it: noise_table.c's permutation on the raw
 * coordinates, each taken modulo 4096 (no offset, unlike the noise). */
static int wrap12(double v)
{
	double r = v - 4096.0 * floor(v / 4096.0);
	/* An infinite coordinate (a function pattern called at 1e300 * 1e300)
	 * leaves NaN, which no int holds: cube 0 there. */
	return r >= 0 && r < 4096.0 ? (int)r : 0;
}

static int cube_hash(double i, double j, double k)
{
	return noise_hash[noise_hash[noise_hash[wrap12(i)] ^ wrap12(j)] ^ wrap12(k)];
}

static double cell_rand(int h)
{
	return cell_random[h] * (1.0 / 4294967296.0);
}

/* The feature point of unit cube (i, j, k) (cell_table.h). */
static vec3 cell_point(double i, double j, double k)
{
	int h = cube_hash(i, j, k);
	return v3(i + cell_rand(h), j + cell_rand(h + 1), k + cell_rand(h + 2));
}

/* cells: one random value per unit cube. As with checker, a face belongs to
 * the cube above it: POV-Ray nudges the point up by 1e-10 first (measured:
 * the value changes between -1e-10 and -2e-10 on every axis). */
PATTERN_FN(cells)
{
	(void)pt; (void)ctx;
	const double eps = 1e-10;
	return cell_rand(cube_hash(floor(q.x + eps), floor(q.y + eps), floor(q.z + eps)));
}

static double metric_dist(vec3 d, double m, double o)
{
	if (m == 2 || m <= 0)
		return sqrt(d.x * d.x + d.y * d.y + d.z * d.z + o * o);
	if (m == 1)
		return fabs(d.x) + fabs(d.y) + fabs(d.z) + fabs(o);
	return pow(pow(fabs(d.x), m) + pow(fabs(d.y), m) + pow(fabs(d.z), m) + pow(fabs(o), m), 1.0 / m);
}

/* The three nearest feature points' distances and the nearest one. */
struct nearest {
	double d[3];
	vec3 point;
};

/* Offer feature point c at distance d to the three nearest so far. */
static void nearest_add(struct nearest *nr, vec3 c, double d)
{
	if (d < nr->d[0]) {
		nr->d[2] = nr->d[1];
		nr->d[1] = nr->d[0];
		nr->d[0] = d;
		nr->point = c;
	} else if (d < nr->d[1]) {
		nr->d[2] = nr->d[1];
		nr->d[1] = d;
	} else if (d < nr->d[2]) {
		nr->d[2] = d;
	}
}

/* How far v lies outside [lo, lo + 1]. */
static double gap(double v, double lo)
{
	return v < lo ? lo - v : v > lo + 1 ? v - (lo + 1) : 0;
}

/* The three nearest feature points to q: those of the 27 cubes around q's,
 * then of the cubes two away that could hold a nearer one (with metric 1
 * they sometimes do: POV-Ray's F2 agrees with this search at 2400 random
 * points for every metric, not with the 27 cubes alone). */
static void crackle_search(vec3 q, double metric, double offset, struct nearest *nr)
{
	double ci = floor(q.x), cj = floor(q.y), ck = floor(q.z);
	nr->d[0] = nr->d[1] = nr->d[2] = INFINITY;
	nr->point = q;
	/* Counted by whole offsets: past 2^53, ci + 1 is ci and a loop on
	 * the coordinate itself never ended (found by fuzzing). */
	for (int di = -1; di <= 1; di++)
		for (int dj = -1; dj <= 1; dj++)
			for (int dk = -1; dk <= 1; dk++) {
				vec3 c = cell_point(ci + di, cj + dj, ck + dk);
				nearest_add(nr, c, metric_dist(v3_sub(q, c), metric, offset));
			}
	for (int di = -2; di <= 2; di++)
		for (int dj = -2; dj <= 2; dj++)
			for (int dk = -2; dk <= 2; dk++) {
				if (abs(di) < 2 && abs(dj) < 2 && abs(dk) < 2)
					continue;
				double i = ci + di, j = cj + dj, k = ck + dk;
				vec3 g = v3(gap(q.x, i), gap(q.y, j), gap(q.z, k));
				if (metric_dist(g, metric, offset) >= nr->d[2])
					continue;
				vec3 c = cell_point(i, j, k);
				nearest_add(nr, c, metric_dist(v3_sub(q, c), metric, offset));
			}
}

/* crackle: form · (F1, F2, F3) over the nearest feature points' distances
 * in the given metric with the offset as a fourth coordinate (default form <−1, 1, 0>, metric 2); with
 * solid, the noise at the nearest feature point (measured: POV-Ray's solid
 * crackle is bozo's noise there), one flat value per cell. */
PATTERN_FN(crackle)
{
	struct nearest nr;
	double metric = pt->f[0] != 0 ? pt->f[0] : 2;      /* pattern.h: metric f[0], offset f[1], solid n[0] */
	crackle_search(q, metric, pt->f[1], &nr);
	if (pt->n[0])
		return noise3(nr.point, gen_of(pt, ctx));
	vec3 form = pt->form;
	if (form.x == 0 && form.y == 0 && form.z == 0)
		form = v3(-1, 1, 0);
	/* clipped to [0, 1] before frequency and the wave (measured) */
	double v = form.x * nr.d[0] + form.y * nr.d[1] + form.z * nr.d[2];
	return v < 0 ? 0 : v > 1 ? 1 : v;
}

/* The feature point facets takes with metric 1 or 0: of the 81 cubes
 * around q's (the 5 x 5 x 5 block less the cubes two away along two or
 * three axes), with metric 1 the point whose coordinates have the
 * smallest sum, with metric 0 the first (x, then y, then z, from -2).
 * Measured: POV-Ray's facets take a metric-1 distance as the sum of the
 * signed differences and find every metric-0 distance equal; their facets
 * are then unit cubes (every normal of a plane and a sphere in both forms
 * matches this, where crackle's true metric-1 cells matched none). */
static vec3 facets_block_point(vec3 q, double metric)
{
	double ci = floor(q.x), cj = floor(q.y), ck = floor(q.z);
	vec3 best = q;
	double low = INFINITY;
	for (int i = -2; i <= 2; i++)
		for (int j = -2; j <= 2; j++)
			for (int k = -2; k <= 2; k++) {
				if ((abs(i) == 2) + (abs(j) == 2) + (abs(k) == 2) > 1)
					continue;
				vec3 c = cell_point(ci + i, cj + j, ck + k);
				if (metric == 0)
					return c;
				if (c.x + c.y + c.z < low) {
					low = c.x + c.y + c.z;
					best = c;
				}
			}
	return best;
}

/* The feature point the facets normal takes at q: crackle's nearest in
 * the given metric, but for metrics 1 and 0. */
static vec3 facets_point(vec3 q, double metric)
{
	if (metric == 1 || metric == 0)
		return facets_block_point(q, metric);
	struct nearest nr;
	crackle_search(q, metric, 0, &nr);
	return nr.point;
}

/* facets as a value (it is a normal pattern): the nearest cell's value, as
 * solid crackle's. */
PATTERN_FN(facets)
{
	struct nearest nr;
	crackle_search(q, 2, 0, &nr);
	return noise3(nr.point, gen_of(pt, ctx));
}

/* ---- special normal perturbations ---- */

/* The push of the ripples and waves normals: the mean over the sources of
 * s × (q − w_i) / |q − w_i|, s = sin(2π (F d + P)) for ripples and
 * sin(2π (f F d + P)) / f for waves, F and P the pattern's frequency and
 * phase (measured like bumps, kinds.h; one source, then ten). */
static vec3 ripple_push(vec3 q, const struct pattern *pt, const struct pattern_ctx *ctx, bool waves)
{
	int n = wave_count(ctx);
	vec3 g = v3(0, 0, 0);
	for (int i = 0; i < n; i++) {
		vec3 d = v3_sub(q, wave_sources[i].w);
		double r = v3_len(d);
		if (r == 0)
			continue;
		double f = waves ? wave_sources[i].f : 1;
		double F = (float)pt->frequency, P = (float)pt->phase;
		g = v3_madd(g, d, sin(2 * M_PI * (f * F * r + P)) / f / r);
	}
	return v3_scale(g, 1.0 / n);
}

static vec3 unit_or(vec3 v, vec3 fallback)
{
	double l = v3_len(v);
	return l > 0 ? v3_scale(v, 1.0 / l) : fallback;
}

vec3 pattern_normal_in(const struct pattern *pt, vec3 n)
{
	for (int i = pt->nops - 1; i >= 0; i--)
		if (pt->ops[i].kind == POP_TRANSFORM)
			n = mat_normal(&pt->ops[i].xf.fwd, n);
	return n;
}

vec3 pattern_normal_out(const struct pattern *pt, vec3 n)
{
	for (int i = 0; i < pt->nops; i++)
		if (pt->ops[i].kind == POP_TRANSFORM)
			n = mat_normal(&pt->ops[i].xf.inv, n);
	return n;
}

vec3 pattern_dir_out(const struct pattern *pt, vec3 d)
{
	for (int i = 0; i < pt->nops; i++)
		if (pt->ops[i].kind == POP_TRANSFORM)
			d = mat_dir(&pt->ops[i].xf.fwd, d);
	return d;
}

bool pattern_special_normal(const struct pattern *pt, double amount, vec3 p, vec3 n,
                            const struct pattern_ctx *ctx, vec3 *out)
{
	int gen = gen_of(pt, ctx);
	vec3 q = pattern_point_ctx(pt, p, ctx);
	vec3 d;
	switch (pt->kind) {
	case PAT_BUMPS:
		d = v3_scale(dnoise3(q, gen), amount);
		break;
	case PAT_DENTS: {
		double s = noise3(q, gen);
		d = v3_scale(dnoise3(q, gen), amount * s * s * s);
		break;
	}
	case PAT_WRINKLES: {
		/* 10 octaves of |DNoise| per component (measured) */
		d = v3(0, 0, 0);
		double amp = 1, freq = 1;
		for (int i = 0; i < 10; i++, amp *= 0.5, freq *= 2) {
			vec3 o = dnoise3(v3_scale(q, freq), gen);
			d = v3_madd(d, v3(fabs(o.x), fabs(o.y), fabs(o.z)), amp);
		}
		d = v3_scale(d, amount);
		break;
	}
	case PAT_RIPPLES: case PAT_WAVES:
		d = v3_scale(ripple_push(q, pt, ctx, pt->kind == PAT_WAVES), amount);
		break;
	case PAT_QUILTED: {
		/* The offset o from the unit cell's centre times 2/sqrt(3) times
		 * the quilted cubic of |o| (measured through camera ray
		 * perturbation to 3e-4, and on a lit plane). */
		vec3 o = v3(q.x - floor(q.x) - 0.5, q.y - floor(q.y) - 0.5, q.z - floor(q.z) - 0.5);
		double t = v3_len(o), it = 1 - t;
		double c0 = (float)pt->f[0], c1 = (float)pt->f[1];
		double k = c0 * 3 * t * it * it + c1 * 3 * t * t * it + t * t * t;
		d = v3_scale(o, amount * k * 1.154700538);
		break;
	}
	case PAT_FACETS: {
		/* Measured from POV-Ray's renders (normal solved per pixel, within
		 * its 16-bit output): the bump size, accuracy, noise_generator
		 * and, with size, the warps play no part. n faces the ray and is
		 * taken into pattern space like the other special normals. The
		 * cells are crackle's in the pattern's metric, but for metrics 1
		 * and 0 (facets_block_point). */
		double size = pt->vec.x, coords = pt->vec.y;
		double metric = pt->f[0];                          /* pattern.h: facets metric f[0] */
		vec3 np = unit_or(pattern_normal_in(pt, n), n), m;
		if (!(size > 0)) {
			/* POV-Ray leaves the normal alone with size 0 or less
			 * (with coords too it gives noise from cells at infinity). */
			*out = n;
			return true;
		}
		if (coords != 0) {
			/* The crackle cell of q / size (q after the warps); each
			 * tilts n by coords × DNoise at its feature point, less
			 * the part along n. */
			vec3 r = dnoise3(facets_point(v3_scale(q, 1 / size), metric), gen);
			m = v3_madd(np, v3_madd(r, np, -v3_dot(r, np)), coords);
		} else {
			/* The normal snapped to the feature point nearest n / size:
			 * a flat surface keeps one tilted normal. */
			m = facets_point(v3_scale(np, 1 / size), metric);
		}
		*out = unit_or(pattern_normal_out(pt, m), n);
		return true;
	}
	default:
		return false;
	}
	/* The push is added in pattern space, along n too (measured, kinds.h). */
	vec3 np = unit_or(pattern_normal_in(pt, n), n);
	vec3 m = pattern_normal_out(pt, v3_add(np, d));
	*out = unit_or(m, n);
	return true;
}

/* camsample.c: camera samples (see camsample.h): one pinhole ray, or with
 * focal blur the lens samples of POV-Ray's adaptive scheme.
 *
 * Where the lens samples fall: a point of the lens (a disc of radius
 * aperture/4, or with a bokeh the square of half-side aperture/4, drawn
 * in proportion to the bokeh pigment's brightness) and a point of the
 * pixel around (x, y), from a Halton sequence (bases 2 and 3 for the
 * lens, 5 and 7 for the pixel) shifted by an offset hashed from (px, py,
 * sample, purpose), so every pixel sees its own well-spread pattern and
 * the image does not depend on the thread count. POV-Ray draws its own
 * (random) points, so the two agree on average only.
 *
 * When sampling stops, measured from POV-Ray 3.7 (sample counts in its
 * statistics, W1 x H1 renders whose colour is a linear function of the
 * lens position, and bisection on `variance`):
 *  - it checks only at fixed counts, which depend on blur_samples' maximum
 *    M through the size G of POV-Ray's first pattern (4 if M < 7, 7 if
 *    M < 19, 19 if M < 37, else 37): at 4 (G = 4); at 7 (G = 7); at 7, 13
 *    and 19 (G = 19); at 7, 13, 19, 23, 27, 31, 35 and 37 (G = 37); then
 *    every 4 after G; and it always stops at M. A flat area thus takes
 *    7 samples from blur_samples 1, 50 and 13 from 8, 50;
 *  - at a check at or after the minimum it stops when, in every channel,
 *    the variance of the n colours (divided by n) is below
 *        variance * n * X(n) / X(M - 1),
 *    X(k) being the chi-square quantile with k degrees of freedom that is
 *    exceeded with probability `confidence` (fitted to 4 digits at n = 37
 *    to 117, M = 120 and 200, confidence 0.5, 0.75, 0.9, 0.99). Variance
 *    0 thus always takes M samples, as in POV-Ray. */
#include "render/camsample.h"

#include "math/hash.h"
#include "pattern/kinds.h"
#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>

/* Purposes for hash_uniform: 'LENS' in the high bytes, the dimension in
 * the low one. */
enum { PURPOSE_LENS = 0x4c454e00u };

/* The bokeh's sampling table: BOKEH_N x BOKEH_N cells of the unit square. */
enum { BOKEH_N = 128 };

/* The Halton bases of the lens sample's four dimensions: lens u and v,
 * pixel x and y. */
static const uint32_t HALTON_BASES[4] = {2, 3, 5, 7};

/* How many samples' worth of a lens's tables are worked out in advance (a
 * huge blur_samples is not worth 40 bytes a sample; past the tables, what
 * a sample needs is worked out as it is needed), and the degrees of
 * freedom past which the chi-square quantile is Wilson and Hilferty's (the
 * exact one takes a bisection over the incomplete gamma function, too dear
 * to run for each of a huge blur_samples' check points or at each check of
 * a pixel; past this size the two agree within 4e-8 for a confidence up to
 * 0.999, measured). */
enum { LENS_TABLE = 65536 };

struct lens {
	int min, max;
	int ntab;        /* max, but at most LENS_TABLE: the samples the tables hold */
	double *limit;   /* [n], n = 0..ntab: the variance limit at a check point, -1 elsewhere
	                  * (lens_limit works it out past the table) */
	double variance, confidence;
	double scale;    /* the chi-square quantile at max - 1 (1 for max 1) */
	double z;        /* the standard normal quantile exceeded with probability confidence */
	double *halton;  /* [k * (ntab + 1) + n]: Halton point n's coordinate in dimension k
	                  * (radical_inverse(n, HALTON_BASES[k])), worked out once: the
	                  * per-sample integer divisions stalled the pipeline */
	double *turn;    /* [2 * n], [2 * n + 1]: cos and sin of 2 pi times point n's
	                  * coordinate 1, the lens angle before the pixel's shift turns
	                  * it (no sincos per sample) */
	double *col_cdf; /* bokeh: cumulative weight of the columns (BOKEH_N + 1), NULL without */
	double *row_cdf; /* bokeh: per column, cumulative weight of its rows (BOKEH_N x (BOKEH_N + 1)) */
};

/* P(a, x), the regularised lower incomplete gamma function (a > 0, x >= 0):
 * the series below a + 1, the continued fraction above (Numerical
 * Recipes' split). */
static double gamma_p(double a, double x)
{
	if (x <= 0)
		return 0;
	double lead = exp(-x + a * log(x) - lgamma(a));
	if (x < a + 1) {
		double term = 1 / a, sum = term;
		for (int i = 1; i < 10000 && fabs(term) > fabs(sum) * 1e-16; i++) {
			term *= x / (a + i);
			sum += term;
		}
		return sum * lead;
	}
	double b = x + 1 - a, c = 1e300, d = 1 / b, h = d;
	for (int i = 1; i < 10000; i++) {
		double an = -i * (i - a);
		b += 2;
		d = an * d + b;
		if (fabs(d) < 1e-300)
			d = 1e-300;
		c = b + an / c;
		if (fabs(c) < 1e-300)
			c = 1e-300;
		d = 1 / d;
		h *= d * c;
		if (fabs(d * c - 1) < 1e-16)
			break;
	}
	return 1 - lead * h;
}

/* The x that a chi-square variable with k degrees of freedom exceeds with
 * probability q (0 < q < 1), by bisection. */
static double chi2_upper_quantile(int k, double q)
{
	double lo = 0, hi = k + 20 + 20 * sqrt((double)k);
	for (int i = 0; i < 200; i++) {
		double mid = 0.5 * (lo + hi);
		if (mid == lo || mid == hi)
			break; /* converged: further steps change nothing */
		if (1 - gamma_p(0.5 * k, 0.5 * mid) > q)
			lo = mid;
		else
			hi = mid;
	}
	return 0.5 * (lo + hi);
}

/* The z that a standard normal variable exceeds with probability q, by
 * bisection. */
static double normal_upper_quantile(double q)
{
	double lo = -40, hi = 40;
	for (int i = 0; i < 200; i++) {
		double mid = 0.5 * (lo + hi);
		if (0.5 * erfc(mid / M_SQRT2) > q)
			lo = mid;
		else
			hi = mid;
	}
	return 0.5 * (lo + hi);
}

/* chi2_upper_quantile(k, l->confidence), by Wilson and Hilferty's cube
 * past LENS_TABLE degrees of freedom. */
static double lens_chi2(const struct lens *l, int k)
{
	if (k <= LENS_TABLE)
		return chi2_upper_quantile(k, l->confidence);
	double v = 2.0 / (9.0 * k), c = 1 - v + l->z * sqrt(v);
	return k * c * c * c;
}

/* The radical inverse of i in base b (the Halton sequence). */
static double radical_inverse(uint32_t i, uint32_t b)
{
	double inv = 1.0 / b, f = inv, r = 0;
	while (i > 0) {
		r += f * (double)(i % b);
		i /= b;
		f *= inv;
	}
	return r;
}

/* The size of POV-Ray's first sample pattern for a maximum of max. */
static int first_pattern(int max)
{
	return max < 7 ? 4 : max < 19 ? 7 : max < 37 ? 19 : 37;
}

/* Does POV-Ray test for convergence after n samples (maximum max)? */
static bool check_point(int n, int max)
{
	int g = first_pattern(max);
	if (n > g)
		return (n - g) % 4 == 0;
	switch (g) {
	case 4: return n == 4;
	case 7: return n == 7;
	case 19: return n == 7 || n == 13 || n == 19;
	default: return n == 7 || n == 13 || (n >= 19 && n % 4 == 3) || n == 37;
	}
}

int lens_flat_samples(int min, int max)
{
	for (int n = 1; n < max; n++)
		if (n >= min && check_point(n, max))
			return n;
	return max;
}

/* The bokeh pigment's brightness (POV-Ray's grey: 0.297 r + 0.589 g +
 * 0.114 b, negative taken as 0) at the centres of a grid over the unit
 * square, turned into cumulative tables. A bokeh black all over samples
 * the whole square evenly, as POV-Ray does (measured: the mean of x^2
 * over its lens is that of the square). */
static void bokeh_tables(struct lens *l, const struct pigment *pg, const struct scene *s)
{
	int n = BOKEH_N;
	l->col_cdf = malloc((size_t)(n + 1) * sizeof *l->col_cdf);
	l->row_cdf = malloc((size_t)n * (size_t)(n + 1) * sizeof *l->row_cdf);
	if (!l->col_cdf || !l->row_cdf)
		abort();
	struct pattern_ctx ctx = {.normal = {0, 0, 1}, .dir = {0, 0, 1},
	                          .noise_generator = s->gs.noise_generator, .number_of_waves = s->gs.number_of_waves};
	l->col_cdf[0] = 0;
	for (int i = 0; i < n; i++) {
		double *row = l->row_cdf + (size_t)i * (size_t)(n + 1);
		row[0] = 0;
		for (int j = 0; j < n; j++) {
			ctx.p = v3((i + 0.5) / n, (j + 0.5) / n, 0);
			struct rgbft c = pigment_eval(pg, &ctx);
			double g = 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
			row[j + 1] = row[j] + (g > 0 ? g : 0);
		}
		l->col_cdf[i + 1] = l->col_cdf[i] + row[n];
	}
	if (l->col_cdf[n] > 0)
		return;
	for (int i = 0; i < n; i++) {
		double *row = l->row_cdf + (size_t)i * (size_t)(n + 1);
		for (int j = 0; j <= n; j++)
			row[j] = j;
		l->col_cdf[i + 1] = i + 1;
	}
}

/* The variance limit after n samples: -1 where POV-Ray does not check
 * (see the file comment). */
static double lens_limit_at(const struct lens *l, int n)
{
	if (!(n > 0 && n < l->max && check_point(n, l->max)))
		return -1;
	return l->variance == 0 ? 0 : l->variance * n * lens_chi2(l, n) / l->scale;
}

static double lens_limit(const struct lens *l, int n)
{
	return n <= l->ntab ? l->limit[n] : lens_limit_at(l, n);
}

struct lens *lens_new(const struct scene *s)
{
	const struct camera *c = &s->camera;
	struct lens *l = calloc(1, sizeof *l);
	if (!l)
		abort();
	l->max = c->blur_samples_max;
	l->min = c->blur_samples_min;
	l->variance = c->variance;
	l->confidence = c->confidence;
	l->z = normal_upper_quantile(c->confidence);
	l->scale = l->max > 1 ? lens_chi2(l, l->max - 1) : 1;
	l->ntab = l->max < LENS_TABLE ? l->max : LENS_TABLE;
	l->limit = malloc((size_t)(l->ntab + 1) * sizeof *l->limit);
	if (!l->limit)
		abort();
	for (int n = 0; n <= l->ntab; n++)
		l->limit[n] = lens_limit_at(l, n);
	l->halton = malloc(4 * (size_t)(l->ntab + 1) * sizeof *l->halton);
	if (!l->halton)
		abort();
	for (int k = 0; k < 4; k++)
		for (int n = 0; n <= l->ntab; n++)
			l->halton[k * (l->ntab + 1) + n] = radical_inverse((uint32_t)n, HALTON_BASES[k]);
	l->turn = malloc(2 * (size_t)(l->ntab + 1) * sizeof *l->turn);
	if (!l->turn)
		abort();
	for (int n = 0; n <= l->ntab; n++) {
		double phi = 2 * M_PI * l->halton[(l->ntab + 1) + n];
		l->turn[2 * n] = cos(phi);
		l->turn[2 * n + 1] = sin(phi);
	}
	if (c->bokeh)
		bokeh_tables(l, c->bokeh, s);
	return l;
}

void lens_free(struct lens *l)
{
	if (!l)
		return;
	free(l->limit);
	free(l->halton);
	free(l->turn);
	free(l->col_cdf);
	free(l->row_cdf);
	free(l);
}

/* The index i with cdf[i] <= t < cdf[i + 1] among n cells (binary search),
 * and where t falls in that cell (0 to 1) in *frac. */
static int cdf_find(const double *cdf, int n, double t, double *frac)
{
	int lo = 0, hi = n;
	while (hi - lo > 1) {
		int mid = (lo + hi) / 2;
		if (cdf[mid] <= t)
			lo = mid;
		else
			hi = mid;
	}
	/* Skip empty cells (a zero-weight cell can only be landed on at its
	 * left edge). */
	while (lo < n - 1 && cdf[lo + 1] <= t)
		lo++;
	double w = cdf[lo + 1] - cdf[lo];
	*frac = w > 0 ? (t - cdf[lo]) / w : 0.5;
	return lo;
}

/* The bokeh's lens point (lu, lv) for the uniform pair (a, b): in the
 * square [-1/2, 1/2]^2, drawn from the bokeh (its pigment's x to the right
 * and y downwards, as measured: a bokeh bright where y < 0.5 moves the
 * samples up). */
static void bokeh_point(const struct lens *l, double a, double b, double *lu, double *lv)
{
	int n = BOKEH_N;
	double fx, fy;
	int i = cdf_find(l->col_cdf, n, a * l->col_cdf[n], &fx);
	const double *row = l->row_cdf + (size_t)i * (size_t)(n + 1);
	int j = cdf_find(row, n, b * row[n], &fy);
	*lu = (i + fx) / n - 0.5;
	*lv = 0.5 - (j + fy) / n;
}

/* cos and sin of 2 pi times Halton point n's coordinate 1 (unshifted). */
static void lens_turn(const struct lens *l, int n, double *c, double *s)
{
	if (n <= l->ntab) {
		*c = l->turn[2 * n];
		*s = l->turn[2 * n + 1];
		return;
	}
	double phi = 2 * M_PI * radical_inverse((uint32_t)n, HALTON_BASES[1]);
	*c = cos(phi);
	*s = sin(phi);
}

/* Coordinate k of Halton point n shifted by `shift` (in [0, 1)). */
static double lens_dim(const struct lens *l, int k, int n, double shift)
{
	double v = (n <= l->ntab ? l->halton[k * (l->ntab + 1) + n] : radical_inverse((uint32_t)n, HALTON_BASES[k])) +
	           shift;
	return v >= 1 ? v - 1 : v;
}

/* Camera ray perturbation (the camera's `normal`), measured from POV-Ray
 * 3.7 with 16-bit renders of a plane whose colour encodes where each ray
 * meets it (gradient, onion, leopard, granite, bozo, crackle, wood,
 * marble, agate, quilted, bumps, dents, wrinkles, ripples, waves, average;
 * scales, rotations, translations, turbulence; several right vectors and
 * camera turns; all within 3e-4 of the ray's slope, the measurement's
 * precision):
 *  - the pattern is evaluated at (u, v, 0), u and v the image position
 *    from -1/2 to 1/2 whatever the right and up vectors; the camera's own
 *    location and transformations do not move it;
 *  - the ray's unit direction d is perturbed exactly as a surface normal
 *    d facing the ray would be (normal_eval, texture_eval.c): patterns
 *    with a normal of their own push it by their formula at the full
 *    amount, the others tilt it in the pattern's space by 2/15 of the
 *    amount times their numerical slope, and average and normal_map blend
 *    the entries' directions (POV-Ray 3.7 crashes on a normal_map in the
 *    camera; average matches it).
 * facets too (tests/render cam-normal-facets: exact). Known difference:
 * spiral1 with turbulence, whose values differ on surfaces too. */
static vec3 camera_perturb(const struct normal *nm, const struct scene *s, double u, double v, vec3 d)
{
	struct pattern_ctx ctx = {.p = v3(u, v, 0), .normal = d, .dir = d,
	                          .noise_generator = s->gs.noise_generator, .number_of_waves = s->gs.number_of_waves};
	return normal_eval(nm, d, &ctx);
}

/* The camera's ray at (x, y) with lens sample (lu, lv), perturbed by its
 * normal if it has one; false where it has none (camera_ray). */
static bool sample_ray(const struct tracer *tr, double x, double y, int w, int h, double lu, double lv,
                       struct ray *r)
{
	const struct camera *cam = &tr->p->scene->camera;
	if (!camera_ray(cam, x, y, w, h, lu, lv, r))
		return false;
	if (cam->normal)
		r->dir = camera_perturb(cam->normal, tr->p->scene, x / w - 0.5, 0.5 - y / h, r->dir);
	return true;
}

/* Focal blur: the mean colour of the lens samples (see the file comment). */
static rgb focal_blur(struct tracer *tr, const struct lens *l, double x, double y, int w, int h, int px, int py,
                      uint32_t sample, bool *any)
{
	double shift[4];
	for (int k = 0; k < 4; k++)
		shift[k] = hash_uniform((uint32_t)px, (uint32_t)py, sample, PURPOSE_LENS + (uint32_t)k);
	/* On the disc of radius 1/2 (no bokeh), the radius is the square
	 * root of coordinate 0 and the angle 2 pi times coordinate 1: its
	 * shift turns the point by 2 pi shift[1], so the unshifted point's
	 * turn (lens_turn) is turned once more (the same angle, wrapped or
	 * not). */
	bool disc = !l->col_cdf;
	double tc = disc ? cos(2 * M_PI * shift[1]) : 1, ts = disc ? sin(2 * M_PI * shift[1]) : 0;
	/* Welford's running mean and sum of squared deviations per channel. */
	double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
	for (int n = 1; n <= l->max; n++) {
		/* Halton point 0 is the corner: the samples start at 1. */
		double lu, lv;
		if (disc) {
			double rad = 0.5 * sqrt(lens_dim(l, 0, n, shift[0])), c0, s0;
			lens_turn(l, n, &c0, &s0);
			lu = rad * (c0 * tc - s0 * ts);
			lv = rad * (s0 * tc + c0 * ts);
		} else {
			bokeh_point(l, lens_dim(l, 0, n, shift[0]), lens_dim(l, 1, n, shift[1]), &lu, &lv);
		}
		double jx = lens_dim(l, 2, n, shift[2]) - 0.5, jy = lens_dim(l, 3, n, shift[3]) - 0.5;
		struct ray r;
		rgb c = rgb_make(0, 0, 0);
		bool hit = false;
		if (sample_ray(tr, x + jx, y + jy, w, h, lu, lv, &r))
			c = trace_ray(tr, &r, 1, RAY_CAMERA, &hit);
		*any = *any || hit;
		double v[3] = {c.r, c.g, c.b}, inv = 1.0 / n;
		for (int k = 0; k < 3; k++) {
			double d = v[k] - mean[k];
			mean[k] += d * inv;
			m2[k] += d * (v[k] - mean[k]);
		}
		if (n >= l->min) {
			double lim = lens_limit(l, n);
			if (lim >= 0) {
				lim *= n; /* m2 is n times the variance */
				if (m2[0] < lim && m2[1] < lim && m2[2] < lim)
					break;
			}
		}
		/* A huge blur_samples is the user's to stop: the render looks at
		 * its stop flag between tiles, and a pixel can take hours. */
		if ((n & 4095) == 0 && tr->stop && *tr->stop)
			break;
	}
	return rgb_make(mean[0], mean[1], mean[2]);
}

rgb camera_sample(struct tracer *tr, double x, double y, int w, int h, int px, int py, uint32_t sample,
                  bool *any)
{
	const struct camera *cam = &tr->p->scene->camera;
	*any = false;
	if (cam->kind == CAMERA_MESH) {
		/* The mean of the rays that have a face; none: black. */
		rgb sum = rgb_make(0, 0, 0);
		int n = 0;
		/* Distribution 1 shoots only its first ray (camera_mesh_ray). */
		int nrays = cam->mesh->dist == 1 ? 1 : cam->mesh->rays;
		for (int k = 0; k < nrays; k++) {
			struct ray r;
			if (!camera_mesh_ray(cam, x, y, w, h, k, &r))
				continue;
			bool hit = false;
			rgb c = trace_ray(tr, &r, 1, RAY_CAMERA, &hit);
			*any = *any || hit;
			sum = rgb_make(sum.r + c.r, sum.g + c.g, sum.b + c.b);
			n++;
		}
		return n > 0 ? rgb_make(sum.r / n, sum.g / n, sum.b / n) : sum;
	}
	if ((tr->p->features & FEAT_FOCAL_BLUR) && tr->p->lens)
		return focal_blur(tr, tr->p->lens, x, y, w, h, px, py, sample, any);
	struct ray r;
	if (!sample_ray(tr, x, y, w, h, 0, 0, &r))
		return rgb_make(0, 0, 0);
	return trace_ray(tr, &r, 1, RAY_CAMERA, any);
}

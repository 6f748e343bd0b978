/* fractal.c: the fractal patterns julia, mandel and magnet (see kinds.h),
 * in the x-y plane of pattern space.
 *
 * Measured against POV-Ray 3.7's function { pattern { ... } }:
 * - mandel and julia iterate z ← z^p + c (mandel from z = c, julia from
 *   z = the point) and escape when |z|² > 4; the escape at the i-th
 *   iteration (from 0) gives exterior type 1's value i / iterations.
 * - magnet iterates type 1: z ← ((z² + c - 1) / (2z + c - 2))², type 2:
 *   z ← ((z³ + 3(c-1)z + (c-1)(c-2)) / (3z² + 3(c-2)z + (c-1)(c-2) + 1))²,
 *   mandel from z = 0, julia from the point; it stops when |z|² > 10000 or
 *   when |z - 1|² < 0.0001 (the attracting fixed point 1), and both count
 *   as the exterior.
 * - A point that never stops is interior. */
#include "pattern/kinds.h"

#include <math.h>

struct cplx {
	double re, im;
};

static struct cplx cmul(struct cplx a, struct cplx b)
{
	struct cplx r = {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
	return r;
}

static struct cplx cdiv(struct cplx a, struct cplx b)
{
	double d = b.re * b.re + b.im * b.im;
	struct cplx r = {(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
	return r;
}

static struct cplx cadd(struct cplx a, struct cplx b)
{
	struct cplx r = {a.re + b.re, a.im + b.im};
	return r;
}

static struct cplx cscale(struct cplx a, double s)
{
	struct cplx r = {a.re * s, a.im * s};
	return r;
}

/* z^p for an integer p >= 2: squares for 2, 3 and 4 as POV-Ray's
 * optimised cases do, repeated multiplication above. */
static struct cplx cpowi(struct cplx z, int p)
{
	struct cplx r = z;
	for (int i = 1; i < p; i++)
		r = cmul(r, z);
	return r;
}

/* The value of a stopped or finished orbit: type t of the exterior or the
 * interior with factor f; last is the orbit's last point, min_abs the
 * smallest |z| met, it the iteration at which it stopped, n the limit. */
static double color_value(int t, double f, struct cplx last, double min_abs, int it, int n, bool exterior)
{
	switch (t) {
	case 0: return f;
	case 1: return exterior ? (double)it / n : min_abs * f;
	case 2: return last.re * f;
	case 3: return last.im * f;
	case 4: return last.re * last.re * f;
	case 5: return last.im * last.im * f;
	case 6:
		/* measured: |z| times the factor outside, but inside re² + im²
		 * times the factor (POV-Ray's value, factor on one term only) */
		if (exterior)
			return sqrt(last.re * last.re + last.im * last.im) * f;
		return last.re * last.re + last.im * last.im * f;
	case 7: return exterior && f != 0 ? fmod((double)it, f) / f : 0;
	case 8: return exterior && f != 0 ? fmod((double)it, f + 1.0) / f : 0;
	default: return 0;
	}
}

enum frac_kind { FR_POWER, FR_MAGNET1, FR_MAGNET2 };

static double iterate(const struct fractal *fr, enum frac_kind kind, struct cplx z, struct cplx c,
                      bool count_start)
{
	int n = fr->iterations > 0 ? fr->iterations : 1;
	double bail = kind == FR_POWER ? 4.0 : 10000.0;
	/* the smallest |z|² of the orbit: measured to count the start, except
	 * magnet's mandel form's start at 0 */
	double min2 = count_start ? z.re * z.re + z.im * z.im : INFINITY;
	struct cplx one = {1, 0};
	struct cplx c1 = {c.re - 1.0, c.im}, c2 = {c.re - 2.0, c.im};
	struct cplx c1c2 = cmul(c1, c2);
	for (int i = 0; i < n; i++) {
		switch (kind) {
		case FR_POWER:
			z = cadd(cpowi(z, fr->exponent < 2 ? 2 : fr->exponent), c);
			break;
		case FR_MAGNET1: {
			struct cplx num = cadd(cmul(z, z), c1);
			struct cplx den = cadd(cscale(z, 2.0), c2);
			z = cdiv(num, den);
			z = cmul(z, z);
			break;
		}
		case FR_MAGNET2: {
			struct cplx z2 = cmul(z, z);
			struct cplx num = cadd(cadd(cmul(z2, z), cscale(cmul(c1, z), 3.0)), c1c2);
			struct cplx den = cadd(cadd(cadd(cscale(z2, 3.0), cscale(cmul(c2, z), 3.0)), c1c2), one);
			z = cdiv(num, den);
			z = cmul(z, z);
			break;
		}
		}
		double a2 = z.re * z.re + z.im * z.im;
		if (a2 < min2)
			min2 = a2;
		bool stop = a2 > bail;
		if (kind != FR_POWER) {
			double dr = z.re - 1.0;
			stop = stop || dr * dr + z.im * z.im < 0.0001;
		}
		if (stop || isnan(a2))
			return color_value(fr->exterior_type, fr->exterior_factor, z, sqrt(min2), i, n, true);
	}
	return color_value(fr->interior_type, fr->interior_factor, z, sqrt(min2), n, n, false);
}

PATTERN_FN(julia)
{
	(void)ctx;
	struct cplx z = {q.x, q.y}, c = {pt->fractal.c[0], pt->fractal.c[1]};
	return iterate(&pt->fractal, FR_POWER, z, c, true);
}

PATTERN_FN(mandel)
{
	(void)ctx;
	struct cplx c = {q.x, q.y};
	return iterate(&pt->fractal, FR_POWER, c, c, true);
}

/* magnet_type 1 or 2; the julia form iterates from the point with the
 * constant pt->fractal.c, the mandel form from 0 with the point as c. */
PATTERN_FN(magnet)
{
	(void)ctx;
	enum frac_kind k = pt->fractal.magnet_type == 2 ? FR_MAGNET2 : FR_MAGNET1;
	struct cplx p = {q.x, q.y};
	if (pt->fractal.julia) {
		struct cplx c = {pt->fractal.c[0], pt->fractal.c[1]};
		return iterate(&pt->fractal, k, p, c, true);
	}
	struct cplx zero = {0, 0};
	return iterate(&pt->fractal, k, zero, p, false);
}

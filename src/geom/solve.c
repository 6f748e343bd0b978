/* solve.c: polynomial root solvers (see solve.h).
 *
 * Everything but solve_quadratic first rescales the polynomial exactly, by
 * powers of two: t = s x with s chosen so that the roots x are of order
 * one, and the coefficients divided by the binade of the largest. The
 * closed forms then cannot overflow, and their fixed tolerances mean the
 * same at every scale.
 *
 * The closed forms return unpolished roots together with a "doubt"
 * interval: the places where the sign of a discriminant lies within its
 * rounding error, so that two close real roots and a complex pair cannot
 * be told apart (a ray grazing a surface), or everything if Ferrari's
 * factorisation did not converge. solve_poly hands an interval of interest
 * that meets the doubt to the Sturm solver, which decides by counting sign
 * changes. Every root found, by any path, is then polished by Newton steps
 * on the exactly rescaled original polynomial. */
#include "geom/solve.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define EPS DBL_EPSILON
#define MAXN SOLVE_MAX_DEGREE

int solve_quadratic(double a, double b, double c, double r[2])
{
	if (a == 0) {
		if (b == 0)
			return 0;
		r[0] = -c / b;
		return 1;
	}
	double disc = b * b - 4 * a * c;
	if (disc < 0)
		return 0;
	if (disc == 0) {
		r[0] = -b / (2 * a);
		return 1;
	}
	/* q has the sign of b, so -b and the root never cancel. */
	double q = -0.5 * (b + copysign(sqrt(disc), b));
	double t0 = q / a, t1 = q != 0 ? c / q : -t0;
	if (t0 > t1) {
		double tmp = t0;
		t0 = t1;
		t1 = tmp;
	}
	r[0] = t0;
	r[1] = t1;
	return 2;
}

/* ---- evaluation and polishing ---- */

/* p(x) by Horner's rule for p = c[0] + ... + c[n] x^n. */
static double eval(const double *c, int n, double x)
{
	double p = c[n];
	for (int i = n - 1; i >= 0; i--)
		p = p * x + c[i];
	return p;
}

/* p(x), with p'(x) in *d and in *mag the sum of |c_i x^i|, the scale of the
 * rounding error in p(x). */
static double eval_d(const double *c, int n, double x, double *d, double *mag)
{
	double p = c[n], dp = 0, m = fabs(c[n]), ax = fabs(x);
	for (int i = n - 1; i >= 0; i--) {
		dp = dp * x + p;
		p = p * x + c[i];
		m = m * ax + fabs(c[i]);
	}
	*d = dp;
	*mag = m;
	return p;
}

/* p, p' and the rounding scale of p at a point (see eval_d). */
struct pval {
	double p, d, mag;
};

/* Newton's method on p from x, kept strictly inside (lo, hi) (half-way to
 * the neighbouring roots, so that two close roots never merge) and stopped
 * once a step is below the last bits of x or fails to reduce |p|, i.e.
 * once p(x) is rounding noise. *at gets p's values at the result. */
static double polish(const double *c, int n, double x, double lo, double hi, struct pval *at)
{
	struct pval v;
	v.p = eval_d(c, n, x, &v.d, &v.mag);
	for (int it = 0; it < 24 && v.p != 0 && v.d != 0; it++) {
		double step = v.p / v.d, x1 = x - step;
		if (!(x1 > lo && x1 < hi) || x1 == x)
			break;
		struct pval v1;
		v1.p = eval_d(c, n, x1, &v1.d, &v1.mag);
		if (!(fabs(v1.p) < fabs(v.p)))
			break;
		x = x1;
		v = v1;
		if (fabs(step) <= 4 * EPS * fabs(x))
			break;
	}
	*at = v;
	return x;
}

static void sort_roots(double *r, int k)
{
	for (int i = 1; i < k; i++) {
		double v = r[i];
		int j = i;
		for (; j > 0 && r[j - 1] > v; j--)
			r[j] = r[j - 1];
		r[j] = v;
	}
}

/* Sort, drop non-finite values and exact duplicates; returns the count. */
static int tidy_roots(double *r, int k)
{
	int n = 0;
	for (int i = 0; i < k; i++)
		if (isfinite(r[i]))
			r[n++] = r[i];
	sort_roots(r, n);
	int m = 0;
	for (int i = 0; i < n; i++)
		if (m == 0 || r[i] != r[m - 1])
			r[m++] = r[i];
	return m;
}

/* A root x of p whose rounding uncertainty (the noise in p over |p'|) is
 * large is near a multiple root, which Newton on p only finds to about the
 * square root of the precision. The nearby root of p' is then the better
 * estimate if p is within its rounding noise there. */
static double refine_multiple(const double *c, int n, double x, double lo, double hi, const struct pval *at)
{
	double noise = 8 * n * EPS * at->mag;
	if (n < 2 || fabs(at->p) > noise || fabs(at->d) * 1e-11 * (1 + fabs(x)) > noise)
		return x;
	double dc[MAXN], d, m;
	struct pval dv;
	for (int i = 0; i < n; i++)
		dc[i] = (i + 1) * c[i + 1];
	double xc = polish(dc, n - 1, x, lo, hi, &dv);
	double pc = eval_d(c, n, xc, &d, &m);
	return fabs(pc) <= 8 * n * EPS * m ? xc : x;
}

/* Polish every root of p in the window (wlo, whi) on p itself, each within
 * half the distance to its neighbours; roots clearly outside the window
 * (by more than the closed forms' error could account for) are left as
 * they are, to be discarded. Returns the tidied count. */
static int polish_roots(const double *c, int n, double *r, int k, double wlo, double whi)
{
	double orig[MAXN];
	k = tidy_roots(r, k);
	for (int i = 0; i < k; i++)
		orig[i] = r[i];
	for (int i = 0; i < k; i++) {
		double margin = 1e-4 * (1 + fabs(orig[i]));
		if (orig[i] < wlo - margin || orig[i] > whi + margin)
			continue;
		double lo = i > 0 ? 0.5 * orig[i - 1] + 0.5 * orig[i] : -INFINITY;
		double hi = i < k - 1 ? 0.5 * orig[i] + 0.5 * orig[i + 1] : INFINITY;
		struct pval at;
		double x = polish(c, n, orig[i], lo, hi, &at);
		r[i] = refine_multiple(c, n, x, lo, hi, &at);
	}
	return tidy_roots(r, k);
}

/* ---- exact rescaling ---- */

/* The binary exponent of a finite nonzero x, as frexp's (x = f 2^e with
 * 0.5 <= |f| < 1), read from its bits; subnormals get the smallest normal
 * exponent, which is all the rescaling needs. */
static int expo(double x)
{
	uint64_t b;
	memcpy(&b, &x, sizeof b);
	return (int)((b >> 52) & 0x7ff) - 1022;
}

/* x 2^k, exactly unless the result leaves the normal range. */
static double times_pow2(double x, int k)
{
	if (k < -1022 || k > 1023)
		return ldexp(x, k);
	uint64_t b = (uint64_t)(k + 1023) << 52;
	double p;
	memcpy(&p, &b, sizeof p);
	return x * p;
}

/* e[i] = c[i] 2^(k i - g) for i = 0..n, exact barring underflow of terms
 * that are negligible anyway, with k chosen so that the roots of e are of
 * order one (2^k approximates max |c_i/c_n|^(1/(n-i)), which bounds them)
 * and g so that the largest |e[i]| lies in [0.5, 1). Requires c[n] != 0;
 * returns s = 2^k, the factor that takes a root of e back to one of c. */
static double rescale(const double *c, int n, double *e)
{
	int en = expo(c[n]), k = INT_MIN;
	for (int i = 0; i < n; i++) {
		if (c[i] == 0)
			continue;
		int d = n - i, diff = expo(c[i]) - en;
		int kk = diff >= 0 ? (diff + d - 1) / d : -(-diff / d);
		if (kk > k)
			k = kk;
	}
	if (k == INT_MIN)
		k = 0; /* c[n] x^n: every root is 0 */
	int g = INT_MIN, ex[MAXN + 1];
	for (int i = 0; i <= n; i++) {
		ex[i] = c[i] != 0 ? expo(c[i]) + k * i : INT_MIN;
		if (ex[i] > g)
			g = ex[i];
	}
	for (int i = 0; i <= n; i++)
		e[i] = c[i] == 0 ? 0 : times_pow2(c[i], k * i - g);
	return times_pow2(1.0, k);
}

/* ---- doubt intervals ---- */

struct doubt {
	double lo, hi; /* empty when lo > hi */
};

static void doubt_add(struct doubt *dz, double lo, double hi)
{
	if (lo < dz->lo)
		dz->lo = lo;
	if (hi > dz->hi)
		dz->hi = hi;
}

/* ---- closed forms on monic polynomials with roots of order one ---- */

/* Real roots of x^2 + al x + be, a factor of a polynomial of degree n whose
 * rounding-error scale at x is sum scale[i] |x|^i, relative error err, and
 * whose other factor (monic, degree n-2, ascending) is g (NULL: 1). When
 * the discriminant lies within what the errors can move it by (which is
 * 4 |delta p(x0)| / |g(x0)| at the vertex x0), the neighbourhood of x0 goes
 * into the doubt interval. Returns the count written to r (0..2). */
static int quad_roots(double al, double be, const double *scale, int n, const double *g, double err,
                      double *r, struct doubt *dz)
{
	double disc = fma(al, al, -4 * be);
	double x0 = -0.5 * al;
	double S = 0, ax = fabs(x0);
	for (int i = n; i >= 0; i--)
		S = S * ax + scale[i];
	double gx = g ? eval(g, n - 2, x0) : 1;
	double unc = 4 * EPS * (al * al + 4 * fabs(be));
	unc += gx != 0 ? 8 * (err + 8 * n * EPS) * S / fabs(gx) : INFINITY;
	if (fabs(disc) <= unc) {
		double w = 2 * sqrt(fabs(disc) + unc) + 8 * EPS * (1 + ax);
		doubt_add(dz, x0 - w, x0 + w);
	}
	if (!(disc >= 0))
		return 0;
	if (disc == 0) {
		r[0] = x0;
		return 1;
	}
	double q = -0.5 * (al + copysign(sqrt(disc), al));
	r[0] = q;
	r[1] = be / q;
	return 2;
}

/* Real roots of x^3 + a x^2 + b x + c: three by the trigonometric method
 * when the discriminant is clearly negative, one by Cardano's formula (with
 * the cube root taken on the side where nothing cancels) when clearly
 * positive, and otherwise the double-root form, with the double root's
 * neighbourhood put in doubt. With `largest` set, only the largest root
 * is wanted (in the three-root case the others are not computed). */
static int cubic_monic(double a, double b, double c, bool largest, double *r, struct doubt *dz)
{
	double a3 = a / 3;
	double Q = (a * a - 3 * b) / 9;
	double R = (a * (2 * a * a - 9 * b) + 27 * c) / 54;
	double Q3 = Q * Q * Q, R2 = R * R;
	double D = R2 - Q3;
	/* Bounds on the rounding errors of Q, R and so D (with a margin). */
	double eQ = 4 * EPS * (a * a + 3 * fabs(b)) / 9;
	double eR = 6 * EPS * (fabs(a) * (2 * a * a + 9 * fabs(b)) + 27 * fabs(c)) / 54;
	double eD = 4 * (2 * fabs(R) * eR + 3 * Q * Q * eQ + 4 * EPS * (R2 + fabs(Q3)));
	if (D < -eD) {
		double sq = sqrt(Q);
		double cs = R / (Q * sq);
		double th = acos(cs < -1 ? -1 : cs > 1 ? 1 : cs);
		const double tp = 2.0943951023931954923; /* 2 pi / 3 */
		if (largest) {
			r[0] = -2 * sq * cos(th / 3 + tp) - a3;
			return 1;
		}
		r[0] = -2 * sq * cos(th / 3) - a3;
		r[1] = -2 * sq * cos(th / 3 + tp) - a3;
		r[2] = -2 * sq * cos(th / 3 - tp) - a3;
		return 3;
	}
	if (D > eD) {
		double A = -copysign(cbrt(fabs(R) + sqrt(D)), R);
		double B = A != 0 ? Q / A : 0;
		r[0] = A + B - a3;
		return 1;
	}
	/* R^2 = Q^3 within rounding: roots -2 cbrt(R) - a/3 and a double one at
	 * cbrt(R) - a/3 (a triple root if R = 0). */
	double cr = cbrt(R);
	r[0] = -2 * cr - a3;
	r[1] = cr - a3;
	double m = fabs(r[1]), S = 1;
	S = ((S * m + fabs(a)) * m + fabs(b)) * m + fabs(c);
	double sep = fabs(r[0] - r[1]);
	double w = 4 * fmax(sep > 0 ? sqrt(16 * EPS * S / sep) : INFINITY, cbrt(16 * EPS * S));
	doubt_add(dz, r[1] - w, r[1] + w);
	return r[0] == r[1] ? 1 : 2;
}

/* The backward error of the factorisation (x^2 + v0 x + v1)(x^2 + v2 x + v3)
 * of x^4 + a x^3 + b x^2 + c x + d, each coefficient's error relative to the
 * sum of the magnitudes of the products that form it (written to scale,
 * ascending, for the error estimate of the roots). */
static double factor_error(const double v[4], const double m[5], double scale[5])
{
	double a1 = v[0], b1 = v[1], a2 = v[2], b2 = v[3];
	double e[4] = {b1 * b2 - m[0], a1 * b2 + a2 * b1 - m[1], b1 + b2 + a1 * a2 - m[2], a1 + a2 - m[3]};
	scale[0] = fabs(b1 * b2) + fabs(m[0]);
	scale[1] = fabs(a1 * b2) + fabs(a2 * b1) + fabs(m[1]);
	scale[2] = fabs(b1) + fabs(b2) + fabs(a1 * a2) + fabs(m[2]);
	scale[3] = fabs(a1) + fabs(a2) + fabs(m[3]);
	scale[4] = 1;
	double err = 0;
	for (int i = 0; i < 4; i++) {
		double ei = scale[i] > 0 ? fabs(e[i]) / scale[i] : 0;
		if (!(ei <= err))
			err = ei; /* also catches NaN */
	}
	return err;
}

/* One Newton step on the factorisation: the Jacobian of the four
 * coefficient equations in (v0, v1, v2, v3), solved by Gaussian elimination
 * with partial pivoting. Returns false if the system is singular. */
static bool factor_step(double v[4], const double m[5])
{
	double a1 = v[0], b1 = v[1], a2 = v[2], b2 = v[3];
	double J[4][5] = {
		{0, b2, 0, b1, b1 * b2 - m[0]},
		{b2, a2, b1, a1, a1 * b2 + a2 * b1 - m[1]},
		{a2, 1, a1, 1, b1 + b2 + a1 * a2 - m[2]},
		{1, 0, 1, 0, a1 + a2 - m[3]},
	};
	for (int col = 0; col < 4; col++) {
		int piv = col;
		for (int i = col + 1; i < 4; i++)
			if (fabs(J[i][col]) > fabs(J[piv][col]))
				piv = i;
		if (!(fabs(J[piv][col]) > 0))
			return false;
		if (piv != col)
			for (int j = 0; j < 5; j++) {
				double t = J[col][j];
				J[col][j] = J[piv][j];
				J[piv][j] = t;
			}
		for (int i = col + 1; i < 4; i++) {
			double f = J[i][col] / J[col][col];
			for (int j = col; j < 5; j++)
				J[i][j] -= f * J[col][j];
		}
	}
	double x[4];
	for (int i = 3; i >= 0; i--) {
		double s = J[i][4];
		for (int j = i + 1; j < 4; j++)
			s -= J[i][j] * x[j];
		x[i] = s / J[i][i];
	}
	for (int i = 0; i < 4; i++) {
		if (!isfinite(x[i]))
			return false;
		v[i] -= x[i];
	}
	return true;
}

/* Real roots of the monic quartic m (ascending, m[4] = 1). Ferrari: with y
 * the largest root of the resolvent cubic, x^4 + a x^3 + b x^2 + c x + d =
 * (x^2 + a/2 x + y/2)^2 - (E x + F)^2, which factors into two real
 * quadratics. The factors are then refined by Newton's method on their
 * four coefficients while the backward error decreases; a factorisation
 * left with a large error puts everything in doubt. */
static int quartic_monic(const double m[5], double *r, struct doubt *dz)
{
	double a = m[3], b = m[2], c = m[1], d = m[0];
	if (d == 0) {
		r[0] = 0;
		return 1 + cubic_monic(a, b, c, false, r + 1, dz);
	}
	double rc[4] = {-(a * a * d - 4 * b * d + c * c), a * c - 4 * d, -b, 1};
	double ys[3];
	struct doubt ignore = {INFINITY, -INFINITY};
	int ny = cubic_monic(rc[2], rc[1], rc[0], true, ys, &ignore);
	double y = ys[0], below = -INFINITY;
	for (int i = 1; i < ny; i++)
		if (ys[i] > y)
			y = ys[i];
	for (int i = 0; i < ny; i++)
		if (ys[i] < y && ys[i] > below)
			below = ys[i];
	/* Polish y without letting Newton wander off to a smaller root. */
	struct pval yv;
	double ylo = below == -INFINITY ? y - 1e-3 * (1 + fabs(y)) : 0.5 * (below + y);
	y = polish(rc, 3, y, ylo, INFINITY, &yv);

	double e = 0.25 * a * a - b + y, f = 0.25 * y * y - d, h = 0.5 * a * y - c; /* h = 2 E F */
	double E, F;
	if (e >= f) {
		E = sqrt(fmax(e, 0));
		F = E > 0 ? h / (2 * E) : sqrt(fmax(f, 0));
	} else {
		F = sqrt(fmax(f, 0));
		E = F > 0 ? h / (2 * F) : sqrt(fmax(e, 0));
	}
	double v[4] = {0.5 * a - E, 0.5 * y - F, 0.5 * a + E, 0.5 * y + F};
	/* The smaller constant term from the product, where nothing cancels. */
	if (fabs(v[1]) < fabs(v[3])) {
		if (v[3] != 0)
			v[1] = d / v[3];
	} else if (v[1] != 0) {
		v[3] = d / v[1];
	}
	double scale[5], err = factor_error(v, m, scale);
	for (int it = 0; it < 8 && err > 32 * EPS; it++) {
		double w[4] = {v[0], v[1], v[2], v[3]}, s2[5];
		if (!factor_step(w, m))
			break;
		double e2 = factor_error(w, m, s2);
		if (!(e2 < err))
			break;
		for (int i = 0; i < 4; i++)
			v[i] = w[i];
		for (int i = 0; i < 5; i++)
			scale[i] = s2[i];
		err = e2;
	}
	if (!(err <= 1e-10))
		doubt_add(dz, -INFINITY, INFINITY);
	double g1[3] = {v[3], v[2], 1}, g2[3] = {v[1], v[0], 1};
	int k = quad_roots(v[0], v[1], scale, 4, g1, err, r, dz);
	return k + quad_roots(v[2], v[3], scale, 4, g2, err, r + k, dz);
}

/* ---- root isolation: brackets, critical points, Sturm sequences ---- */

/* The root of p in a bracket (a, b) with p(a), p(b) of opposite signs:
 * Newton steps while they stay inside the shrinking bracket and shrink it
 * at least as fast as bisection would, bisection otherwise; the first
 * iterate is the false-position point. */
static double bracketed_root(const double *p, int n, double a, double b, double fa, double fb)
{
	double xl = fa < 0 ? a : b, xh = fa < 0 ? b : a; /* p(xl) < 0 < p(xh) */
	double x = a - fa * (b - a) / (fb - fa);
	if (!(x > fmin(a, b) && x < fmax(a, b)))
		x = 0.5 * a + 0.5 * b;
	double dxold = fabs(b - a), dx = dxold;
	double d, mag, f = eval_d(p, n, x, &d, &mag);
	for (int it = 0; it < 200; it++) {
		if (f == 0)
			return x;
		if (f < 0)
			xl = x;
		else
			xh = x;
		double xn = d != 0 ? x - f / d : NAN;
		if (!(xn > fmin(xl, xh) && xn < fmax(xl, xh) && fabs(2 * f) <= fabs(dxold * d)))
			xn = 0.5 * xl + 0.5 * xh;
		dxold = dx;
		dx = fabs(xn - x);
		if (xn == x || dx <= EPS * fabs(xn) || xn == xl || xn == xh)
			return xn;
		x = xn;
		f = eval_d(p, n, x, &d, &mag);
	}
	return x;
}

/* The sign of p(x), 0 when |p(x)| is within its rounding noise. */
static int noisy_sign(const double *p, int n, double x)
{
	double d, m, v = eval_d(p, n, x, &d, &m);
	if (fabs(v) <= 8 * (n + 1) * EPS * m)
		return 0;
	return v > 0 ? 1 : -1;
}

/* The distinct roots of p (degree n >= 1) in the finite interval (lo, hi),
 * ascending, through its critical points: the roots of p' in (lo, hi),
 * found the same way, cut the interval into pieces on which p is
 * monotone; a piece holds a root exactly when p changes sign across it,
 * and a critical point where p is within rounding noise of zero is a
 * multiple root. Only direct evaluations of p decide, so this is immune to
 * the cancellation that can spoil a Sturm sequence; it is the Sturm
 * solver's fallback where the sequence cannot be trusted. */
static int crit_roots(const double *p, int n, double lo, double hi, double *r)
{
	if (n == 1) {
		double x = -p[0] / p[1];
		if (x > lo && x < hi) {
			r[0] = x;
			return 1;
		}
		return 0;
	}
	double dp[MAXN], pts[MAXN + 1];
	for (int i = 0; i < n; i++)
		dp[i] = (i + 1) * p[i + 1];
	int m = crit_roots(dp, n - 1, lo, hi, pts + 1);
	pts[0] = lo;
	pts[m + 1] = hi;
	double val[MAXN + 1];
	int sg[MAXN + 1];
	for (int i = 0; i <= m + 1; i++) {
		val[i] = eval(p, n, pts[i]);
		/* Interior critical points may be roots; at the ends only the raw
		 * sign matters, so that a root just inside is still bracketed. */
		sg[i] = (i == 0 || i == m + 1) ? (val[i] > 0) - (val[i] < 0) : noisy_sign(p, n, pts[i]);
	}
	int k = 0;
	for (int i = 0; i <= m; i++) {
		if (i > 0 && sg[i] == 0)
			r[k++] = pts[i];
		if (sg[i] * sg[i + 1] < 0)
			r[k++] = bracketed_root(p, n, pts[i], pts[i + 1], val[i], val[i + 1]);
	}
	return k;
}

struct sturm {
	int len;                      /* polynomials in the sequence */
	int deg[MAXN + 1];
	double p[MAXN + 1][MAXN + 1]; /* p[k][i]: coefficient of x^i */
};

/* The Sturm sequence of e (degree n >= 1): p0 = e made monic, p1 = p0'/n,
 * p(k+1) = -(p(k-1) mod p(k)), each scaled to a leading coefficient of
 * magnitude one. Alongside, a first-order bound on the absolute error of
 * every coefficient is carried through the divisions. Returns false when
 * the sequence cannot be trusted: some remainder's leading coefficient is
 * not clearly above its error (its degree, and so every sign count, is
 * then uncertain: a near-multiple root, or two roots, real or complex,
 * much closer together than the polynomial's scale). */
static bool sturm_build(struct sturm *s, const double *e, int n)
{
	double E[MAXN + 1][MAXN + 1];
	s->deg[0] = n;
	for (int i = 0; i < n; i++) {
		s->p[0][i] = e[i] / e[n];
		E[0][i] = EPS * fabs(s->p[0][i]);
	}
	s->p[0][n] = 1;
	E[0][n] = 0;
	s->deg[1] = n - 1;
	for (int i = 0; i < n; i++) {
		s->p[1][i] = (i + 1) * s->p[0][i + 1] / n;
		E[1][i] = (i + 1) * E[0][i + 1] / n + 2 * EPS * fabs(s->p[1][i]);
	}
	int k = 2;
	while (s->deg[k - 1] > 0) {
		int da = s->deg[k - 2], db = s->deg[k - 1];
		const double *B = s->p[k - 1], *EB = E[k - 1];
		double r[MAXN + 1], er[MAXN + 1];
		for (int i = 0; i <= da; i++) {
			r[i] = s->p[k - 2][i];
			er[i] = E[k - 2][i];
		}
		for (int j = da - db; j >= 0; j--) {
			double q = r[j + db] / B[db];
			double eq = (er[j + db] + fabs(q) * EB[db]) / fabs(B[db]) + EPS * fabs(q);
			r[j + db] = 0;
			for (int i = 0; i < db; i++) {
				double t = q * B[i];
				r[j + i] -= t;
				er[j + i] += fabs(q) * EB[i] + eq * fabs(B[i]) + EPS * (fabs(r[j + i]) + fabs(t));
			}
		}
		int dr = db - 1;
		while (dr >= 0 && r[dr] == 0 && er[dr] == 0)
			dr--; /* exactly zero: exact arithmetic, not cancellation */
		if (dr < 0)
			return false; /* exact multiple root */
		if (!(fabs(r[dr]) > 4 * er[dr]))
			return false;
		double sc = 1 / fabs(r[dr]);
		for (int i = 0; i <= dr; i++) {
			s->p[k][i] = -r[i] * sc;
			E[k][i] = (er[i] + EPS * fabs(r[i])) * sc;
		}
		s->deg[k] = dr;
		k++;
	}
	s->len = k;
	return true;
}

/* Sign changes in the sequence at x (zeros skipped). */
static int sturm_changes(const struct sturm *s, double x)
{
	int ch = 0, last = 0;
	for (int k = 0; k < s->len; k++) {
		double v = eval(s->p[k], s->deg[k], x);
		int sg = (v > 0) - (v < 0);
		if (sg) {
			if (last && sg != last)
				ch++;
			last = sg;
		}
	}
	return ch;
}

/* The one distinct root of p0 in (a, b], va being the sign changes at a.
 * If p changes sign across the interval the root is bracketed; otherwise
 * it would be of even multiplicity, which a trusted sequence rules out but
 * rounding may still mimic: Sturm bisection then closes in on it, and it
 * counts only if p is within rounding noise of zero there. Returns false
 * for no root. */
static bool sturm_refine(const struct sturm *s, double a, double b, int va, double *root)
{
	const double *p = s->p[0];
	int n = s->deg[0];
	double fa = eval(p, n, a), fb = eval(p, n, b);
	for (int it = 0; it < 2200; it++) {
		if (fb == 0) {
			*root = b;
			return true;
		}
		if (fa != 0 && (fa < 0) != (fb < 0)) {
			*root = bracketed_root(p, n, a, b, fa, fb);
			return true;
		}
		double mid = 0.5 * a + 0.5 * b;
		if (!(mid > a && mid < b))
			break;
		int vm = sturm_changes(s, mid);
		if (va - vm >= 1) {
			b = mid;
			fb = eval(p, n, b);
		} else {
			a = mid;
			va = vm;
			fa = eval(p, n, a);
		}
	}
	*root = 0.5 * a + 0.5 * b;
	return noisy_sign(p, n, *root) == 0;
}

/* Fujiwara's bound on the magnitude of the roots of the monic m. */
static double root_bound(const double *m, int n)
{
	double B = 0;
	for (int i = 0; i < n; i++) {
		double v = i == 0 ? 0.5 * fabs(m[0]) : fabs(m[i]);
		if (v > 0) {
			double t = pow(v, 1.0 / (n - i));
			if (t > B)
				B = t;
		}
	}
	return 2 * B;
}

#define STURM_STACK 160

/* The distinct roots of e (degree n >= 1) in (lo, hi), ascending: count
 * them by the Sturm sequence's sign changes, isolate each by bisection,
 * refine; through the critical points instead where the sequence cannot
 * be trusted. */
static int sturm_roots(const double *e, int n, double lo, double hi, double *r)
{
	struct sturm s;
	bool trusted = sturm_build(&s, e, n);
	double B = root_bound(s.p[0], n) * 1.0625 + DBL_MIN;
	if (lo < -B)
		lo = -B;
	if (hi > B)
		hi = B;
	if (!(lo < hi))
		return 0;
	if (!trusted)
		return crit_roots(s.p[0], n, lo, hi, r);
	struct {
		double a, b;
		int va, vb, depth;
	} st[STURM_STACK];
	int sp = 0, k = 0;
	st[0].a = lo;
	st[0].b = hi;
	st[0].va = sturm_changes(&s, lo);
	st[0].vb = sturm_changes(&s, hi);
	st[0].depth = 0;
	sp = 1;
	while (sp > 0 && k < n) {
		sp--;
		double a = st[sp].a, b = st[sp].b;
		int va = st[sp].va, vb = st[sp].vb, depth = st[sp].depth;
		int cnt = va - vb;
		if (cnt <= 0)
			continue;
		if (cnt == 1) {
			double x;
			if (sturm_refine(&s, a, b, va, &x) && x < hi)
				r[k++] = x;
			continue;
		}
		double mid = 0.5 * a + 0.5 * b;
		if (!(mid > a && mid < b) || depth >= STURM_STACK - 10 || sp + 2 > STURM_STACK) {
			r[k++] = mid; /* a cluster below the resolution: one root */
			continue;
		}
		int vm = sturm_changes(&s, mid);
		st[sp].a = mid; st[sp].b = b; st[sp].va = vm; st[sp].vb = vb; st[sp].depth = depth + 1;
		sp++;
		st[sp].a = a; st[sp].b = mid; st[sp].va = va; st[sp].vb = vm; st[sp].depth = depth + 1;
		sp++;
	}
	return k;
}

/* ---- the driver ---- */

int solve_poly(const double *c, int degree, double tmin, double tmax, bool sturm, double *roots)
{
	if (degree < 0 || degree > MAXN || !(tmin < tmax))
		return 0;
	for (int i = 0; i <= degree; i++)
		if (!isfinite(c[i]))
			return 0;
	int n = degree;
	while (n > 0 && c[n] == 0)
		n--;
	/* Over a finite interval, a leading term below the rounding error of
	 * the others everywhere in it only adds a root far outside. */
	double T = fmax(fabs(tmin), fabs(tmax));
	while (n > 0 && isfinite(T)) {
		double rest = 0, lead = fabs(c[n]);
		for (int i = n - 1; i >= 0; i--) {
			rest = rest * T + fabs(c[i]);
			lead *= T;
		}
		if (isfinite(lead) && lead <= EPS * rest)
			n--;
		else
			break;
	}
	if (n <= 0)
		return 0;

	double e[MAXN + 1], r[MAXN];
	double s = rescale(c, n, e);
	double lo = tmin / s, hi = tmax / s;
	int k;
	if (n == 1) {
		r[0] = -e[0] / e[1];
		k = 1;
	} else {
		struct doubt dz = {INFINITY, -INFINITY};
		k = -1;
		if (!sturm && n <= 4) {
			double m[5];
			for (int i = 0; i < n; i++)
				m[i] = e[i] / e[n];
			m[n] = 1;
			if (n == 2) {
				double sc[3] = {fabs(m[0]), fabs(m[1]), 1};
				k = quad_roots(m[1], m[0], sc, 2, NULL, 0, r, &dz);
			} else if (n == 3) {
				k = cubic_monic(m[2], m[1], m[0], false, r, &dz);
			} else {
				k = quartic_monic(m, r, &dz);
			}
			if (dz.lo <= hi && dz.hi >= lo)
				k = -1; /* in doubt where it matters */
		}
		if (k < 0)
			k = sturm_roots(e, n, lo, hi, r);
	}
	k = polish_roots(e, n, r, k, lo, hi);
	int cnt = 0;
	for (int i = 0; i < k; i++) {
		double t = r[i] * s;
		if (isfinite(t) && t > tmin && t < tmax)
			roots[cnt++] = t;
	}
	return cnt;
}

int solve_cubic(const double c[4], double r[3])
{
	return solve_poly(c, 3, -INFINITY, INFINITY, false, r);
}

int solve_quartic(const double c[5], double r[4])
{
	return solve_poly(c, 4, -INFINITY, INFINITY, false, r);
}

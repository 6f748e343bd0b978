/* poly.c: poly { order, <coefficients> [sturm] }, and cubic and quartic,
 * which are polys of order 3 and 4: the surface f(x, y, z) = 0 of a
 * polynomial of total degree 2..7.
 *
 * POV-Ray's coefficient order (from the manual's table, confirmed by
 * rendering poly and the equivalent polynomial { xyz(i,j,k): } side by side
 * for every order): the monomials x^i y^j z^k, i + j + k <= order, with i
 * descending, then j descending, then k descending, i.e.
 *     for i = n..0, for j = n-i..0, for k = n-i-j..0.
 * For a quartic: x^4, x^3y, x^3z, x^3, x^2y^2, x^2yz, x^2y, x^2z^2, x^2z,
 * x^2, xy^3, ..., z, 1. */
#include "geom/shapes.h"
#include "geom/solve.h"

#include <stdlib.h>

#define POLY_MAX_ORDER 7
#define POLY_MAX_TERMS 120 /* (7+1)(7+2)(7+3)/6 */

/* POV-Ray's inside test is f < 1e-4, an absolute tolerance on f (measured
 * with povray's inside() on scaled copies of one surface). */
#define POLY_INSIDE_TOL 1e-4

struct poly {
	struct object base;
	int order;
	bool sturm;
	double coef[POLY_MAX_TERMS]; /* in POV-Ray's order */
};

static int poly_terms(int n)
{
	return (n + 1) * (n + 2) * (n + 3) / 6;
}

/* P[i][m]: the coefficient of s^m in (o + d s)^i, i = 0..n. */
static void binomial_powers(double o, double d, int n, double P[POLY_MAX_ORDER + 1][POLY_MAX_ORDER + 1])
{
	P[0][0] = 1;
	for (int i = 1; i <= n; i++) {
		P[i][i] = P[i - 1][i - 1] * d;
		for (int m = i - 1; m > 0; m--)
			P[i][m] = P[i - 1][m] * o + P[i - 1][m - 1] * d;
		P[i][0] = P[i - 1][0] * o;
	}
}

/* The coefficients out[0..n] (out[m] multiplying s^m) of f(o + s d): f is
 * nested as sum_i X^i sum_j Y^j sum_k c_ijk Z^k in POV-Ray's order, and
 * each power of a coordinate is a binomial expansion in s, so the
 * substitution is exact up to rounding and costs a few hundred
 * multiply-adds at order 7. */
static void poly_along(const struct poly *P, vec3 o, vec3 d, double *out)
{
	int n = P->order, idx = 0;
	double X[POLY_MAX_ORDER + 1][POLY_MAX_ORDER + 1], Y[POLY_MAX_ORDER + 1][POLY_MAX_ORDER + 1],
	       Z[POLY_MAX_ORDER + 1][POLY_MAX_ORDER + 1];
	binomial_powers(o.x, d.x, n, X);
	binomial_powers(o.y, d.y, n, Y);
	binomial_powers(o.z, d.z, n, Z);
	for (int m = 0; m <= n; m++)
		out[m] = 0;
	for (int i = n; i >= 0; i--) {
		double H[POLY_MAX_ORDER + 1] = {0}; /* sum_j Y^j (...), degree n-i */
		bool hz = true;
		for (int j = n - i; j >= 0; j--) {
			double G[POLY_MAX_ORDER + 1] = {0}; /* sum_k c Z^k, degree n-i-j */
			bool gz = true;
			for (int k = n - i - j; k >= 0; k--) {
				double c = P->coef[idx++];
				if (c == 0)
					continue;
				gz = false;
				for (int m = 0; m <= k; m++)
					G[m] += c * Z[k][m];
			}
			if (gz)
				continue;
			hz = false;
			for (int a = 0; a <= n - i - j; a++)
				for (int b = 0; b <= j; b++)
					H[a + b] += G[a] * Y[j][b];
		}
		if (hz)
			continue;
		for (int a = 0; a <= n - i; a++)
			for (int b = 0; b <= i; b++)
				out[a + b] += H[a] * X[i][b];
	}
}

/* f(p), and its gradient into *g when g is not NULL. */
static double poly_eval(const struct poly *P, vec3 p, vec3 *g)
{
	int n = P->order, idx = 0;
	double px[POLY_MAX_ORDER + 1], py[POLY_MAX_ORDER + 1], pz[POLY_MAX_ORDER + 1];
	px[0] = py[0] = pz[0] = 1;
	for (int i = 1; i <= n; i++) {
		px[i] = px[i - 1] * p.x;
		py[i] = py[i - 1] * p.y;
		pz[i] = pz[i - 1] * p.z;
	}
	double f = 0, gx = 0, gy = 0, gz = 0;
	for (int i = n; i >= 0; i--)
		for (int j = n - i; j >= 0; j--)
			for (int k = n - i - j; k >= 0; k--) {
				double c = P->coef[idx++];
				if (c == 0)
					continue;
				f += c * px[i] * py[j] * pz[k];
				if (g) {
					if (i > 0)
						gx += c * i * px[i - 1] * py[j] * pz[k];
					if (j > 0)
						gy += c * j * px[i] * py[j - 1] * pz[k];
					if (k > 0)
						gz += c * k * px[i] * py[j] * pz[k - 1];
				}
			}
	if (g)
		*g = v3(gx, gy, gz);
	return f;
}

/* The crossings tmin < t < tmax, ascending, into t (room for the order);
 * returns how many. The direction is normalised and the origin moved to
 * the ray's closest approach to the object's origin, where the surface's
 * features usually are, so that the coefficients in s stay of the size of
 * the object rather than of the distance to it. */
static int poly_roots(const struct poly *P, const struct ray *ray, double tmin, double tmax, double *t)
{
	double len = v3_len(ray->dir);
	if (!(len > 0) || !isfinite(len))
		return 0;
	vec3 u = v3_scale(ray->dir, 1 / len);
	double sc = -v3_dot(ray->org, u);
	if (!isfinite(sc))
		return 0;
	vec3 p = v3_madd(ray->org, u, sc);
	double c[POLY_MAX_ORDER + 1], s[POLY_MAX_ORDER];
	poly_along(P, p, u, c);
	int n = solve_poly(c, P->order, tmin * len - sc, tmax * len - sc, P->sturm, s);
	int cnt = 0;
	for (int i = 0; i < n; i++) {
		double ti = (sc + s[i]) / len;
		if (ti > tmin && ti < tmax && isfinite(ti))
			t[cnt++] = ti;
	}
	return cnt;
}

static bool poly_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t[POLY_MAX_ORDER];
	if (!poly_roots((const struct poly *)o, r, tmin, tmax, t))
		return false;
	h->t = t[0];
	h->part = 0;
	return true;
}

static int poly_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[POLY_MAX_ORDER];
	int n = poly_roots((const struct poly *)o, r, tmin, tmax, t);
	return object_hits_from_roots(o, t, n, out, max);
}

static bool poly_inside(const struct object *o, vec3 p)
{
	return poly_eval((const struct poly *)o, p, NULL) < POLY_INSIDE_TOL;
}

/* The gradient of f; at a singular point of the surface, where it
 * vanishes, +y rather than a zero vector. */
static vec3 poly_normal(const struct object *o, vec3 p, const struct hit *h)
{
	(void)h;
	vec3 g;
	poly_eval((const struct poly *)o, p, &g);
	if (!(isfinite(g.x) && isfinite(g.y) && isfinite(g.z)) || (g.x == 0 && g.y == 0 && g.z == 0))
		return v3(0, 1, 0);
	return g;
}

/* Unbounded, as in POV-Ray. */
static struct aabb poly_bounds(const struct object *o)
{
	(void)o;
	return (struct aabb){v3(-INFINITY, -INFINITY, -INFINITY), v3(INFINITY, INFINITY, INFINITY)};
}

static struct object *poly_copy(const struct object *o)
{
	struct poly *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct poly *)o;
	return &c->base;
}

static const struct object_ops poly_ops = {
	.name = "poly",
	.intersect = poly_intersect,
	.all_hits = poly_all_hits,
	.inside = poly_inside,
	.normal = poly_normal,
	.bounds = poly_bounds,
	.copy = poly_copy,
};

/* Returns NULL for an order outside 2..7 (the parser reports it). */
struct object *poly_new(int order, const double *coef, bool sturm, struct srcpos pos)
{
	if (order < 2 || order > POLY_MAX_ORDER || !coef)
		return NULL;
	struct poly *P = calloc(1, sizeof *P);
	if (!P) abort();
	object_init(&P->base, &poly_ops, pos);
	P->order = order;
	P->sturm = sturm;
	for (int i = 0; i < poly_terms(order); i++)
		P->coef[i] = coef[i];
	return &P->base;
}

/* sweep.c: sphere_sweep, the union of the spheres whose centre and radius
 * follow a spline (see sweep.h).
 *
 * Each piece of the spline is a polynomial of degree 1 or 3 in s on [0,1]
 * for the centre C(s) and the radius R(s). Along a ray o + t u (u a unit
 * vector) the sphere at s is crossed at t = q(s) -+ sqrt(E(s)), where
 * q = u.(C - o) is the distance along the ray to the centre's foot and
 * E = R^2 - |w|^2, w being C - o less its component along u (E is a
 * polynomial of degree 2 or 6, formed from w so that nothing cancels for
 * distant rays). Where E > 0 over an interval of s the spheres there cover
 * one interval of the ray, [min (q - sqrt E), max (q + sqrt E)], since the
 * crossings move continuously with s; the ray meets the solid in the union
 * of these intervals over the pieces and the intervals of s between the
 * roots of E. POV-Ray 3.7 finds the same surface (measured: its linear
 * sweep is this tube to 10 digits; for b_spline and cubic_spline its first
 * hit is the smallest entry into any swept sphere).
 *
 * The extremes are found on a grid of s and refined by bisection on the
 * sign of the derivative, which is exact to rounding, so that the hit is
 * where the tangent sphere touches the ray and the normal is p - C(s) at
 * that s. */
#include "geom/sweep.h"

#include "geom/solve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One piece: c[k] holds the coefficients of s^k of x, y, z and the radius. */
struct piece {
	double c[4][4];
	struct aabb box; /* the piece's spheres lie in it (its Bezier hull, grown) */
};

struct sweep {
	struct object base;
	enum sweep_spline kind;
	int deg;       /* 1 (linear) or 3 */
	int n;         /* pieces */
	struct piece *pc; /* owned */
	struct aabb bounds; /* POV-Ray's box (see sweep_bounds) */
	double tol;
};

/* One interval of the ray inside the solid, with the piece and the s of
 * the sphere that gives each end. */
struct span {
	double t0, t1;
	double s0, s1;
	int p0, p1;
};

static double poly_eval(const double *c, int deg, double s)
{
	double v = c[deg];
	for (int k = deg - 1; k >= 0; k--)
		v = v * s + c[k];
	return v;
}

/* out (degree 2 deg) += sign * a * b, both of degree deg. */
static void poly_mul_add(double *out, const double *a, const double *b, int deg, double sign)
{
	for (int i = 0; i <= deg; i++)
		for (int j = 0; j <= deg; j++)
			out[i + j] += sign * a[i] * b[j];
}

static vec3 piece_center(const struct piece *pc, int deg, double s)
{
	vec3 c = v3(0, 0, 0);
	for (int k = deg; k >= 0; k--)
		c = v3(c.x * s + pc->c[k][0], c.y * s + pc->c[k][1], c.z * s + pc->c[k][2]);
	return c;
}

/* The polynomials of one piece along one ray: q (degree deg), its
 * derivative, E (degree 2 deg) and its derivative. */
struct ray_poly {
	int deg;
	double q[4], dq[3], e[7], de[6];
};

static void ray_poly_init(struct ray_poly *rp, const struct piece *pc, int deg, vec3 o, vec3 u)
{
	memset(rp, 0, sizeof *rp);
	rp->deg = deg;
	double w[3][4], r[4];
	for (int k = 0; k <= deg; k++) {
		vec3 c = v3(pc->c[k][0], pc->c[k][1], pc->c[k][2]);
		if (k == 0)
			c = v3_sub(c, o);
		double along = v3_dot(c, u);
		rp->q[k] = along;
		vec3 perp = v3_madd(c, u, -along);
		w[0][k] = perp.x;
		w[1][k] = perp.y;
		w[2][k] = perp.z;
		r[k] = pc->c[k][3];
	}
	poly_mul_add(rp->e, r, r, deg, 1);
	for (int j = 0; j < 3; j++)
		poly_mul_add(rp->e, w[j], w[j], deg, -1);
	for (int k = 1; k <= deg; k++)
		rp->dq[k - 1] = k * rp->q[k];
	for (int k = 1; k <= 2 * deg; k++)
		rp->de[k - 1] = k * rp->e[k];
}

/* f(s) = sigma q(s) - sqrt(E(s)): the entry (sigma 1) or minus the exit
 * (sigma -1) of the sphere at s. */
static double f_val(const struct ray_poly *rp, double sigma, double s)
{
	double e = poly_eval(rp->e, 2 * rp->deg, s);
	return sigma * poly_eval(rp->q, rp->deg, s) - sqrt(e > 0 ? e : 0);
}

/* The sign of f'(s), as that of 2 sigma q' sqrt(E) - E'. */
static double f_slope(const struct ray_poly *rp, double sigma, double s)
{
	double e = poly_eval(rp->e, 2 * rp->deg, s);
	return 2 * sigma * poly_eval(rp->dq, rp->deg - 1, s) * sqrt(e > 0 ? e : 0) -
	       poly_eval(rp->de, 2 * rp->deg - 1, s);
}

/* The smallest f on [a, b] (where E >= 0), at *at. A grid of samples, each
 * local minimum of it refined by bisection on the slope's sign where it
 * changes from - to + around it. */
static double f_min(const struct ray_poly *rp, double sigma, double a, double b, double *at)
{
	enum { GRID_MAX = 16 };
	int k = rp->deg == 1 ? 2 : GRID_MAX;
	double s[GRID_MAX + 1], v[GRID_MAX + 1];
	for (int i = 0; i <= k; i++) {
		s[i] = i == k ? b : a + (b - a) * i / k;
		v[i] = f_val(rp, sigma, s[i]);
	}
	double best = INFINITY;
	for (int i = 0; i <= k; i++) {
		if ((i > 0 && v[i - 1] < v[i]) || (i < k && v[i + 1] < v[i]))
			continue;
		if (v[i] < best) {
			best = v[i];
			*at = s[i];
		}
		double lo = s[i > 0 ? i - 1 : 0], hi = s[i < k ? i + 1 : k];
		if (!(f_slope(rp, sigma, lo) < 0 && f_slope(rp, sigma, hi) > 0))
			continue;
		for (int it = 0; it < 200; it++) {
			double mid = 0.5 * (lo + hi);
			if (mid <= lo || mid >= hi)
				break;
			if (f_slope(rp, sigma, mid) < 0)
				lo = mid;
			else
				hi = mid;
		}
		double m = 0.5 * (lo + hi), fm = f_val(rp, sigma, m);
		if (fm < best) {
			best = fm;
			*at = m;
		}
	}
	return best;
}

/* The spans of piece i along the ray (o, unit u, |d| = len), appended to
 * out (room for 4 more needed: E has at most 6 roots); returns the new
 * count. t is in the ray's own parameter (divided by len). */
static int piece_spans(const struct sweep *sw, int i, vec3 o, vec3 u, double len, struct span *out, int n)
{
	struct ray_poly rp;
	ray_poly_init(&rp, &sw->pc[i], sw->deg, o, u);
	double cut[9];
	int m = solve_poly(rp.e, 2 * sw->deg, 0, 1, false, cut + 1);
	/* A linear piece has no spheres where its radius is negative
	 * (POV-Ray's, measured: a sweep from radius -0.5 to 0.5 is hit only
	 * on its positive half); the curved ones keep theirs. */
	double rlo = sw->pc[i].c[0][3], rhi = rlo + sw->pc[i].c[1][3];
	if (sw->deg == 1 && (rlo < 0) != (rhi < 0)) {
		double z = rlo / (rlo - rhi);
		int k = m + 1;
		while (k > 1 && cut[k - 1] > z) {
			cut[k] = cut[k - 1];
			k--;
		}
		cut[k] = z;
		m++;
	}
	cut[0] = 0;
	cut[m + 1] = 1;
	for (int j = 0; j <= m; j++) {
		double a = cut[j], b = cut[j + 1], mid = 0.5 * (a + b);
		if (!(poly_eval(rp.e, 2 * sw->deg, mid) > 0))
			continue;
		if (sw->deg == 1 && !(rlo + (rhi - rlo) * mid > 0))
			continue;
		struct span *sp = &out[n++];
		sp->t0 = f_min(&rp, 1, a, b, &sp->s0) / len;
		sp->t1 = -f_min(&rp, -1, a, b, &sp->s1) / len;
		sp->p0 = sp->p1 = i;
	}
	return n;
}

static int span_cmp(const void *a, const void *b)
{
	const struct span *x = a, *y = b;
	return x->t0 < y->t0 ? -1 : x->t0 > y->t0;
}

/* The crossings of the ray with tmin < t < tmax, ascending, up to max,
 * from the union of every piece's spans. */
static int sweep_crossings(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                           int max)
{
	const struct sweep *sw = (const struct sweep *)o;
	double len = sqrt(v3_dot(r->dir, r->dir));
	if (!(len > 0))
		return 0;
	vec3 u = v3_scale(r->dir, 1 / len);
	tmin = fmax(tmin, sw->tol / len);
	struct span local[256], *sp = local;
	int cap = 256, n = 0;
	for (int i = 0; i < sw->n; i++) {
		/* A cheap test before the piece: its box on the whole line. */
		if (!object_ray_meets_box(sw->pc[i].box, r, -INFINITY, INFINITY))
			continue;
		if (n + 4 > cap) {
			struct span *bigger = malloc((size_t)cap * 2 * sizeof *bigger);
			if (!bigger) abort();
			memcpy(bigger, sp, (size_t)n * sizeof *sp);
			if (sp != local)
				free(sp);
			sp = bigger;
			cap *= 2;
		}
		n = piece_spans(sw, i, r->org, u, len, sp, n);
	}
	qsort(sp, (size_t)n, sizeof *sp, span_cmp);
	int nh = 0;
	for (int i = 0; i < n && nh < max;) {
		struct span cur = sp[i++];
		while (i < n && sp[i].t0 <= cur.t1) {
			if (sp[i].t1 > cur.t1) {
				cur.t1 = sp[i].t1;
				cur.s1 = sp[i].s1;
				cur.p1 = sp[i].p1;
			}
			i++;
		}
		if (cur.t0 >= tmax)
			break;
		if (cur.t0 > tmin)
			out[nh++] = (struct hit){.t = cur.t0, .obj = o, .part = cur.p0, .u = cur.s0};
		if (nh < max && cur.t1 > tmin && cur.t1 < tmax)
			out[nh++] = (struct hit){.t = cur.t1, .obj = o, .part = cur.p1, .u = cur.s1};
	}
	if (sp != local)
		free(sp);
	return nh;
}

static bool sweep_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hit one;
	if (sweep_crossings(o, r, tmin, tmax, &one, 1) == 0)
		return false;
	h->t = one.t;
	h->part = one.part;
	h->u = one.u;
	return true;
}

static int sweep_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                          int max)
{
	return sweep_crossings(o, r, tmin, tmax, out, max);
}

/* Inside the sphere of some s of some piece: the smallest of
 * |p - C(s)|^2 - R(s)^2 over [0, 1], at the ends or where its derivative
 * (degree 2 deg - 1) vanishes, is below zero. */
static bool sweep_inside(const struct object *o, vec3 p)
{
	const struct sweep *sw = (const struct sweep *)o;
	int deg = sw->deg;
	for (int i = 0; i < sw->n; i++) {
		const struct piece *pc = &sw->pc[i];
		if (p.x < pc->box.lo.x || p.y < pc->box.lo.y || p.z < pc->box.lo.z || p.x > pc->box.hi.x ||
		    p.y > pc->box.hi.y || p.z > pc->box.hi.z)
			continue;
		double f[7] = {0}, df[6], w[3][4], r[4];
		for (int k = 0; k <= deg; k++) {
			w[0][k] = pc->c[k][0] - (k == 0 ? p.x : 0);
			w[1][k] = pc->c[k][1] - (k == 0 ? p.y : 0);
			w[2][k] = pc->c[k][2] - (k == 0 ? p.z : 0);
			r[k] = pc->c[k][3];
		}
		for (int j = 0; j < 3; j++)
			poly_mul_add(f, w[j], w[j], deg, 1);
		poly_mul_add(f, r, r, deg, -1);
		for (int k = 1; k <= 2 * deg; k++)
			df[k - 1] = k * f[k];
		double s[8];
		int m = solve_poly(df, 2 * deg - 1, 0, 1, false, s);
		s[m++] = 0;
		s[m++] = 1;
		for (int j = 0; j < m; j++)
			if (poly_eval(f, 2 * deg, s[j]) < 0)
				return true;
	}
	return false;
}

static vec3 sweep_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct sweep *sw = (const struct sweep *)o;
	int i = h->part >= 0 && h->part < sw->n ? h->part : 0;
	const struct piece *pc = &sw->pc[i];
	vec3 n = v3_sub(p, piece_center(pc, sw->deg, h->u));
	/* POV-Ray's normal is (p - C) / R: inward where the radius is
	 * negative (measured on a b_spline of radii -0.5 to 0.5). */
	double rad[4] = {pc->c[0][3], pc->c[1][3], pc->c[2][3], pc->c[3][3]};
	return poly_eval(rad, sw->deg, h->u) < 0 ? v3_neg(n) : n;
}

static struct aabb sweep_bounds(const struct object *o)
{
	return ((const struct sweep *)o)->bounds;
}

static struct object *sweep_copy(const struct object *o)
{
	const struct sweep *sw = (const struct sweep *)o;
	struct sweep *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *sw;
	c->pc = malloc((size_t)sw->n * sizeof *c->pc);
	if (!c->pc) abort();
	memcpy(c->pc, sw->pc, (size_t)sw->n * sizeof *c->pc);
	return &c->base;
}

static void sweep_destroy(struct object *o)
{
	free(((struct sweep *)o)->pc);
}

static const struct object_ops sweep_ops = {
	.name = "sphere_sweep",
	.intersect = sweep_intersect,
	.all_hits = sweep_all_hits,
	.inside = sweep_inside,
	.normal = sweep_normal,
	.bounds = sweep_bounds,
	.copy = sweep_copy,
	.destroy = sweep_destroy,
};

int sweep_min_spheres(enum sweep_spline kind)
{
	return kind == SWEEP_LINEAR ? 2 : 4;
}

/* The power coefficients of piece i from the spheres it uses (x, y, z, r
 * of each in p[j][0..3]). */
static void piece_coefficients(enum sweep_spline kind, const double (*p)[4], double c[4][4])
{
	for (int j = 0; j < 4; j++) {
		switch (kind) {
		case SWEEP_LINEAR:
			c[0][j] = p[0][j];
			c[1][j] = p[1][j] - p[0][j];
			c[2][j] = c[3][j] = 0;
			break;
		case SWEEP_B_SPLINE:
			c[0][j] = (p[0][j] + 4 * p[1][j] + p[2][j]) / 6;
			c[1][j] = (p[2][j] - p[0][j]) / 2;
			c[2][j] = (p[0][j] - 2 * p[1][j] + p[2][j]) / 2;
			c[3][j] = (-p[0][j] + 3 * p[1][j] - 3 * p[2][j] + p[3][j]) / 6;
			break;
		case SWEEP_CUBIC:
			c[0][j] = p[1][j];
			c[1][j] = (p[2][j] - p[0][j]) / 2;
			c[2][j] = (2 * p[0][j] - 5 * p[1][j] + 4 * p[2][j] - p[3][j]) / 2;
			c[3][j] = (-p[0][j] + 3 * p[1][j] - 3 * p[2][j] + p[3][j]) / 2;
			break;
		}
	}
}

/* A box holding every sphere of a piece: its Bezier control points (the
 * curve of centre and radius lies in their hull) grown by the largest
 * control radius. */
static struct aabb piece_box(const double c[4][4], int deg)
{
	double b[4][4];
	for (int j = 0; j < 4; j++) {
		if (deg == 1) {
			b[0][j] = c[0][j];
			b[1][j] = c[0][j] + c[1][j];
		} else {
			b[0][j] = c[0][j];
			b[1][j] = c[0][j] + c[1][j] / 3;
			b[2][j] = c[0][j] + 2 * c[1][j] / 3 + c[2][j] / 3;
			b[3][j] = c[0][j] + c[1][j] + c[2][j] + c[3][j];
		}
	}
	double rmax = 0;
	struct aabb box = aabb_empty();
	for (int k = 0; k <= deg; k++) {
		rmax = fmax(rmax, fabs(b[k][3]));
		box = aabb_add_point(box, v3(b[k][0], b[k][1], b[k][2]));
	}
	vec3 g = v3(rmax, rmax, rmax);
	/* Rounding in the coefficients: a little room. */
	g = v3_add(g, v3_scale(v3_sub(box.hi, box.lo), 1e-9));
	return (struct aabb){v3_sub(box.lo, g), v3_add(box.hi, g)};
}

struct object *sweep_new(enum sweep_spline kind, const vec3 *center, const double *radius, int n,
                         struct srcpos pos)
{
	struct sweep *sw = malloc(sizeof *sw);
	if (!sw) abort();
	object_init(&sw->base, &sweep_ops, pos);
	sw->kind = kind;
	sw->deg = kind == SWEEP_LINEAR ? 1 : 3;
	sw->n = kind == SWEEP_LINEAR ? n - 1 : n - 3;
	sw->tol = 1e-6;
	sw->pc = malloc((size_t)sw->n * sizeof *sw->pc);
	if (!sw->pc) abort();
	for (int i = 0; i < sw->n; i++) {
		double p[4][4] = {{0}};
		for (int j = 0; j <= sw->deg; j++) {
			p[j][0] = center[i + j].x;
			p[j][1] = center[i + j].y;
			p[j][2] = center[i + j].z;
			p[j][3] = radius[i + j];
		}
		piece_coefficients(kind, (const double (*)[4])p, sw->pc[i].c);
		sw->pc[i].box = piece_box(sw->pc[i].c, sw->deg);
	}
	/* POV-Ray's min_extent/max_extent (measured): every given sphere's
	 * box, the radius doubled for cubic_spline. */
	double grow = kind == SWEEP_CUBIC ? 2 : 1;
	sw->bounds = aabb_empty();
	for (int i = 0; i < n; i++) {
		double r = grow * fabs(radius[i]);
		vec3 g = v3(r, r, r);
		sw->bounds = aabb_union(sw->bounds, (struct aabb){v3_sub(center[i], g), v3_add(center[i], g)});
	}
	return &sw->base;
}

void sweep_set_tolerance(struct object *o, double tol)
{
	((struct sweep *)o)->tol = tol;
}

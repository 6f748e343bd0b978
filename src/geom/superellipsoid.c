/* superellipsoid.c: superellipsoid { <e, n> }, the surface
 *   F(x,y,z) = (|x|^p + |y|^p)^r + |z|^q - 1 = 0,  p = 2/e, q = 2/n, r = e/n,
 * which lies in the box [-1,1]^3; the inside is F <= 0 (POV-Ray counts the
 * surface as inside).
 *
 * Intersection is a branch-and-bound search for the sign changes of F along
 * the ray that cannot miss a crossing wider than 1e-13 of the ray's path
 * through the box. The path is cut where x, y or z changes sign; on each
 * piece X = |x|, Y = |y|, Z = |z| are affine in t and F increases with each
 * of them, so over any interval F lies between its values at the corners
 * (Xmin, Ymin, Zmin) and (Xmax, Ymax, Zmax) of the box the interval spans.
 * An interval where that range excludes 0 holds no crossing. An interval
 * where a like enclosure of dF/dt excludes 0 holds at most one, present
 * exactly when F's sign differs at its ends; it is then refined by Newton
 * steps kept inside the bracket (bisection when they stray). Other
 * intervals are halved. A tangent touch without a sign change is not a
 * crossing. A fixed budget bounds the work on rays lying in a flat part of
 * the surface (e = n = 2 is an octahedron), where F is 0 all along. */
#include "geom/shapes.h"

#include <float.h>
#include <stdlib.h>

/* Exponents below this (e or n) are raised to it: POV-Ray draws e = 0 as
 * the limiting box-like shape, which this reproduces to well within a
 * pixel, and 2/e stays finite. */
#define SE_MIN_EXPONENT 1e-3

enum {
	SE_DEPTH = 60,     /* deepest halving; 2^-60 is far below the width limit */
	SE_BUDGET = 4000,  /* most evaluations of F per ray in the search */
	SE_NEWTON = 100,   /* most refinement steps per crossing */
};

struct superellipsoid {
	struct object base;
	double p; /* 2/e: the exponent of |x| and |y| */
	double q; /* 2/n: the exponent of |z| */
	double r; /* e/n: the exponent of |x|^p + |y|^p */
};

/* x^e for x >= 0, exact for the common exponents 1 and 2. */
static double powe(double x, double e)
{
	if (e == 1)
		return x;
	if (e == 2)
		return x * x;
	return pow(x, e);
}

/* v^(e-1) from v and v^e (v >= 0), with the limit at v = 0. */
static double pow_m1(double v, double ve, double e)
{
	if (v > 0)
		return ve / v;
	return e > 1 ? 0 : e == 1 ? 1 : INFINITY;
}

/* F at parameter t, with the pieces the enclosures reuse. */
struct sample {
	double t;
	double X, Y, Z;    /* |x|, |y|, |z| */
	double xp, yp, zq; /* X^p, Y^p, Z^q */
	double sr;         /* (xp + yp)^r */
	double f;          /* F */
};

static struct sample sample_at(const struct superellipsoid *s, const struct ray *r, double t)
{
	struct sample a;
	a.t = t;
	a.X = fabs(r->org.x + t * r->dir.x);
	a.Y = fabs(r->org.y + t * r->dir.y);
	a.Z = fabs(r->org.z + t * r->dir.z);
	a.xp = powe(a.X, s->p);
	a.yp = powe(a.Y, s->p);
	a.zq = powe(a.Z, s->q);
	a.sr = powe(a.xp + a.yp, s->r);
	a.f = a.sr + a.zq - 1;
	return a;
}

/* dF/dt at a sample of a piece whose signed direction components are c
 * (c.x = sign(x) dx, ...): q (S^(r-1) (X^(p-1) c.x + Y^(p-1) c.y) + Z^(q-1) c.z)
 * with S = X^p + Y^p. May be infinite or NaN where a term is singular. */
static double slope(const struct superellipsoid *s, const struct sample *a, vec3 c)
{
	double S = a->xp + a->yp;
	double gxy = 0;
	if (c.x != 0)
		gxy += pow_m1(a->X, a->xp, s->p) * c.x;
	if (c.y != 0)
		gxy += pow_m1(a->Y, a->yp, s->p) * c.y;
	double d = gxy != 0 ? pow_m1(S, a->sr, s->r) * gxy : 0;
	if (c.z != 0)
		d += pow_m1(a->Z, a->zq, s->q) * c.z;
	return s->q * d;
}

/* Products of non-negative interval ends where 0 * inf may occur: the
 * result's low end takes 0 and its high end infinity, which only widens
 * the enclosure. */
static double mul_lo(double a, double b) { return a == 0 || b == 0 ? 0 : a * b; }
static double mul_hi(double a, double b)
{
	if (a == 0 || b == 0)
		return isinf(a) || isinf(b) ? INFINITY : 0;
	return a * b;
}

/* Adds c * [lo, hi] to the interval [*slo, *shi]. */
static void add_term(double c, double lo, double hi, double *slo, double *shi)
{
	if (c == 0)
		return;
	if (c > 0) {
		*slo += c * lo;
		*shi += c * hi;
	} else {
		*slo += c * hi;
		*shi += c * lo;
	}
}

/* What the enclosures over [a.t, b.t] say: the interval holds no crossing
 * (returns 0), F is monotone on it (1), or nothing is known (2). */
static int classify(const struct superellipsoid *s, const struct sample *a, const struct sample *b, vec3 c)
{
	double xplo = fmin(a->xp, b->xp), xphi = fmax(a->xp, b->xp);
	double yplo = fmin(a->yp, b->yp), yphi = fmax(a->yp, b->yp);
	double zqlo = fmin(a->zq, b->zq), zqhi = fmax(a->zq, b->zq);
	double slo = xplo + yplo, shi = xphi + yphi;
	double srlo = powe(slo, s->r), srhi = powe(shi, s->r);
	if (srlo + zqlo - 1 > 0 || srhi + zqhi - 1 < 0)
		return 0;
	/* dF/dt = q (S^(r-1) (X^(p-1) cx + Y^(p-1) cy) + Z^(q-1) cz); every
	 * power is monotone in its base, so each factor's range comes from the
	 * ends of its base's range. */
	double u0 = pow_m1(slo, srlo, s->r), u1 = pow_m1(shi, srhi, s->r);
	double ulo = fmin(u0, u1), uhi = fmax(u0, u1);
	double x0 = pow_m1(a->X, a->xp, s->p), x1 = pow_m1(b->X, b->xp, s->p);
	double y0 = pow_m1(a->Y, a->yp, s->p), y1 = pow_m1(b->Y, b->yp, s->p);
	double z0 = pow_m1(a->Z, a->zq, s->q), z1 = pow_m1(b->Z, b->zq, s->q);
	double dlo = 0, dhi = 0;
	add_term(c.x, mul_lo(ulo, fmin(x0, x1)), mul_hi(uhi, fmax(x0, x1)), &dlo, &dhi);
	add_term(c.y, mul_lo(ulo, fmin(y0, y1)), mul_hi(uhi, fmax(y0, y1)), &dlo, &dhi);
	add_term(c.z, fmin(z0, z1), fmax(z0, z1), &dlo, &dhi);
	return dlo > 0 || dhi < 0 ? 1 : 2; /* NaN (inf - inf) proves nothing */
}

/* The crossing in [a.t, b.t], where F's sign differs at the ends and F is
 * monotone (or the interval is too small to tell): safeguarded Newton, to
 * a few ulps of t. An end where F is exactly 0 is the crossing itself. */
static double refine(const struct superellipsoid *s, const struct ray *r, struct sample a, struct sample b,
                     vec3 c, double scale)
{
	if (a.f == 0)
		return a.t;
	if (b.f == 0)
		return b.t;
	bool a_in = a.f < 0;
	double lo = a.t, hi = b.t;
	double t = lo + (hi - lo) * (a.f / (a.f - b.f)); /* the secant's first guess */
	if (!(t > lo && t < hi))
		t = 0.5 * (lo + hi);
	double step_old = hi - lo;
	for (int it = 0; it < SE_NEWTON; it++) {
		struct sample m = sample_at(s, r, t);
		if (m.f == 0)
			return t;
		if ((m.f < 0) == a_in)
			lo = t;
		else
			hi = t;
		double tol = 2 * DBL_EPSILON * (fabs(t) + scale);
		if (hi - lo <= tol)
			return 0.5 * (lo + hi);
		double tn = t - m.f / slope(s, &m, c);
		/* Bisect when Newton leaves the bracket or does not halve the
		 * step of two iterations ago. */
		if (!(tn > lo && tn < hi) || fabs(tn - t) * 2 > step_old)
			tn = 0.5 * (lo + hi);
		step_old = fabs(tn - t);
		if (step_old <= tol)
			return tn;
		t = tn;
	}
	return t;
}

struct node {
	struct sample a, b;
	int depth;
};

/* The crossings in (tmin, tmax), ascending, at most max of them. */
static int crossings(const struct superellipsoid *s, const struct ray *r, double tmin, double tmax, double *out,
                     int max)
{
	const double lim = 1 + 1e-9; /* the box, a hair wide so rounding never clips the surface */
	double ta = tmin, tb = tmax;
	for (int k = 0; k < 3; k++) {
		double o = v3_get(r->org, k), d = v3_get(r->dir, k);
		if (d == 0) {
			if (fabs(o) > lim)
				return 0;
			continue;
		}
		double t1 = (-lim - o) / d, t2 = (lim - o) / d;
		ta = fmax(ta, fmin(t1, t2));
		tb = fmin(tb, fmax(t1, t2));
	}
	double span = tb - ta;
	if (max <= 0 || !(span > 0) || !isfinite(span))
		return 0; /* a miss, or a zero direction */
	/* Cut where a coordinate changes sign. */
	double cut[5];
	int nc = 0;
	cut[nc++] = ta;
	for (int k = 0; k < 3; k++) {
		double d = v3_get(r->dir, k);
		if (d == 0)
			continue;
		double tc = -v3_get(r->org, k) / d;
		if (!(tc > ta && tc < tb))
			continue;
		int i = nc;
		while (i > 1 && cut[i - 1] > tc) {
			cut[i] = cut[i - 1];
			i--;
		}
		cut[i] = tc;
		nc++;
	}
	cut[nc++] = tb;

	double wmin = fmax(1e-13 * span, 8 * DBL_EPSILON * fmax(fabs(ta), fabs(tb)));
	int budget = SE_BUDGET, n = 0;
	struct node stack[SE_DEPTH + 2];
	struct sample prev = sample_at(s, r, ta);
	for (int seg = 0; seg + 1 < nc; seg++) {
		struct sample next = sample_at(s, r, cut[seg + 1]);
		double tm = 0.5 * (cut[seg] + cut[seg + 1]);
		vec3 c = v3(copysign(1, r->org.x + tm * r->dir.x) * r->dir.x,
		            copysign(1, r->org.y + tm * r->dir.y) * r->dir.y,
		            copysign(1, r->org.z + tm * r->dir.z) * r->dir.z);
		int sp = 0;
		stack[sp++] = (struct node){prev, next, 0};
		while (sp > 0) {
			struct node nd = stack[--sp];
			int kind = classify(s, &nd.a, &nd.b, c);
			if (kind == 0)
				continue;
			bool change = (nd.a.f < 0) != (nd.b.f < 0);
			if (kind == 1 || nd.b.t - nd.a.t <= wmin || nd.depth >= SE_DEPTH || budget <= 0) {
				if (!change)
					continue;
				double t = refine(s, r, nd.a, nd.b, c, span);
				if (t > tmin && t < tmax) {
					out[n++] = t;
					if (n == max)
						return n;
				}
				continue;
			}
			budget--;
			struct sample m = sample_at(s, r, 0.5 * (nd.a.t + nd.b.t));
			stack[sp++] = (struct node){m, nd.b, nd.depth + 1};
			stack[sp++] = (struct node){nd.a, m, nd.depth + 1};
		}
		prev = next;
	}
	return n;
}

static bool se_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t;
	if (!crossings((const struct superellipsoid *)o, r, tmin, tmax, &t, 1))
		return false;
	h->t = t;
	h->part = 0;
	return true;
}

/* At most 16 crossings are reported. F is convex in each octant when
 * e, n <= 2 and concave when e, n >= 2, so a line then meets the surface at
 * most twice in each of the four octants it can pass through; mixed
 * exponents have no such bound but come nowhere near 16 in practice. */
static int se_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[16];
	int n = crossings((const struct superellipsoid *)o, r, tmin, tmax, t, max < 16 ? max : 16);
	return object_hits_from_roots(o, t, n, out, max);
}

static bool se_inside(const struct object *o, vec3 p)
{
	const struct superellipsoid *s = (const struct superellipsoid *)o;
	struct ray r = {p, {0, 0, 0}};
	return sample_at(s, &r, 0).f <= 0;
}

/* k * ln v without 0 * inf. */
static double klog(double k, double lnv) { return k == 0 ? 0 : k * lnv; }

/* The gradient's direction, (sign(x) S^(r-1) X^(p-1), sign(y) S^(r-1) Y^(p-1),
 * sign(z) Z^(q-1)) up to the factor q, formed from logarithms so that
 * nothing overflows or underflows at extreme exponents. A component that is
 * infinite (a cusp, e or n > 2) dominates; one that is undefined (0 * inf
 * on the z axis) counts as 0. */
static vec3 se_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct superellipsoid *s = (const struct superellipsoid *)o;
	double X = fabs(p.x), Y = fabs(p.y), Z = fabs(p.z);
	double big = fmax(X, Y), small = fmin(X, Y);
	double lns = big > 0 ? s->p * log(big) + log1p(powe(small / big, s->p)) : -INFINITY;
	double l[3] = {klog(s->r - 1, lns) + klog(s->p - 1, log(X)), klog(s->r - 1, lns) + klog(s->p - 1, log(Y)),
	               klog(s->q - 1, log(Z))};
	double lmax = -INFINITY;
	for (int i = 0; i < 3; i++) {
		if (isnan(l[i]))
			l[i] = -INFINITY;
		lmax = fmax(lmax, l[i]);
	}
	if (lmax == -INFINITY)
		return v3_dot(p, p) > 0 ? p : v3(0, 1, 0);
	double g[3];
	for (int i = 0; i < 3; i++)
		g[i] = isinf(lmax) ? (l[i] == lmax ? 1 : 0) : exp(l[i] - lmax);
	return v3(copysign(g[0], p.x), copysign(g[1], p.y), copysign(g[2], p.z));
}

/* POV-Ray's box is the unit cube widened by 1e-4 each way (measured:
 * min_extent of superellipsoid { <0.5,0.5> } is -1.0001 on every axis,
 * and the widened cube is what the object's transform moves). */
static struct aabb se_bounds(const struct object *o)
{
	return (struct aabb){{-1.0001, -1.0001, -1.0001}, {1.0001, 1.0001, 1.0001}};
}

static struct object *se_copy(const struct object *o)
{
	struct superellipsoid *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct superellipsoid *)o;
	return &c->base;
}

static const struct object_ops superellipsoid_ops = {
	.name = "superellipsoid",
	.intersect = se_intersect,
	.all_hits = se_all_hits,
	.inside = se_inside,
	.normal = se_normal,
	.bounds = se_bounds,
	.copy = se_copy,
};

/* e and n below SE_MIN_EXPONENT (or not finite) are raised to it. */
struct object *superellipsoid_new(double e, double n, struct srcpos pos)
{
	struct superellipsoid *s = calloc(1, sizeof *s);
	if (!s) abort();
	object_init(&s->base, &superellipsoid_ops, pos);
	if (!(e >= SE_MIN_EXPONENT) || !isfinite(e))
		e = SE_MIN_EXPONENT;
	if (!(n >= SE_MIN_EXPONENT) || !isfinite(n))
		n = SE_MIN_EXPONENT;
	s->p = 2 / e;
	s->q = 2 / n;
	s->r = e / n;
	return &s->base;
}

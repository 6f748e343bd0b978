/* torus.c: torus { major, minor [sturm] }: the points at distance `minor`
 * from the circle of radius `major` in the xz plane around the y axis,
 * which is the quartic (|p|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2). As in
 * POV-Ray 3.7 every root of the quartic is surface, so a spindle torus
 * (r > R) shows its inner lemon-shaped part too. */
#include "geom/shapes.h"
#include "geom/solve.h"

#include <stdlib.h>

struct torus {
	struct object base;
	double R, r; /* major and minor radius, both >= 0 */
	bool sturm;  /* always use the Sturm solver */
};

static const double TWO_PI = 6.28318530717958647692;

/* Narrow [*s0, *s1] to where |o + s d| <= h for one coordinate; false when
 * nothing is left. */
static bool clip_slab(double o, double d, double h, double *s0, double *s1)
{
	if (d == 0)
		return fabs(o) <= h;
	double a = (-h - o) / d, b = (h - o) / d;
	return span_narrow(a, b, s0, s1);
}

/* Narrow [*s0, *s1] to where the ray o + s u (u a unit vector) is within
 * distance rb of the y axis. The discriminant comes from the closest
 * approach to the axis and the near root from q, as for the sphere. */
static bool clip_cylinder(vec3 o, vec3 u, double rb, double *s0, double *s1)
{
	double A = u.x * u.x + u.z * u.z;
	double C = o.x * o.x + o.z * o.z - rb * rb;
	if (A == 0)
		return C <= 0;
	double B = o.x * u.x + o.z * u.z;
	double px = o.x - u.x * (B / A), pz = o.z - u.z * (B / A);
	double h2 = rb * rb - (px * px + pz * pz);
	if (h2 < 0)
		return false;
	double q = -(B + copysign(sqrt(A * h2), B)), a = 0, b = 0;
	if (q != 0) {
		a = q / A;
		b = C / q;
	}
	return span_narrow(a, b, s0, s1);
}

/* The crossings tmin < t < tmax of the ray with the torus, ascending, into
 * t[0..3]; returns how many. To keep the quartic well conditioned the
 * direction is normalised and the origin moved to where the ray enters the
 * bounding thick disc (rho <= R + r, |y| <= r), so that the coefficients
 * are of the size of the torus rather than of the distance to it; roots are
 * mapped back to t afterwards. */
static int torus_roots(const struct torus *T, const struct ray *ray, double tmin, double tmax, double *t)
{
	double R = T->R, r = T->r;
	if (!(r > 0))
		return 0; /* zero-size: nothing to hit */
	double len = v3_len(ray->dir);
	if (!(len > 0) || !isfinite(len))
		return 0;
	vec3 u = v3_scale(ray->dir, 1 / len), o = ray->org;
	/* Widened a hair so that rays touching the torus where it touches its
	 * bounds still reach the solver. */
	double slack = 1e-9 * (R + r);
	double s0 = -INFINITY, s1 = INFINITY;
	if (!clip_slab(o.y, u.y, r + slack, &s0, &s1) || !clip_cylinder(o, u, R + r + slack, &s0, &s1))
		return 0;
	double lo = fmax(s0, tmin * len), hi = fmin(s1, tmax * len);
	if (!(lo <= hi))
		return 0;

	vec3 p = v3_madd(o, u, lo);
	double k = v3_dot(p, u);
	double c[5], s[4];
	int deg;
	if (R == 0) {
		/* A sphere, whose quartic would only have double roots. */
		c[0] = (v3_len(p) - r) * (v3_len(p) + r);
		c[1] = 2 * k;
		c[2] = 1;
		deg = 2;
	} else {
		double rho = sqrt(p.x * p.x + p.z * p.z);
		double G = (rho - R) * (rho + R) + p.y * p.y - r * r; /* |p|^2 - R^2 - r^2 */
		c[4] = 1;
		c[3] = 4 * k;
		c[2] = 4 * k * k + 2 * G + 4 * R * R * u.y * u.y;
		c[1] = 4 * k * G + 8 * R * R * p.y * u.y;
		/* m^2 - 4 R^2 rho^2 as a product, so that it does not cancel. */
		c[0] = ((rho - R - r) * (rho - R + r) + p.y * p.y) * ((rho + R) * (rho + R) + p.y * p.y - r * r);
		deg = 4;
	}
	double w = 1e-7 * (R + r) + 1e-9 * (hi - lo);
	int n = solve_poly(c, deg, -w, hi - lo + w, T->sturm, s);
	int cnt = 0;
	for (int i = 0; i < n; i++) {
		double ti = (lo + s[i]) / len;
		if (ti > tmin && ti < tmax && isfinite(ti))
			t[cnt++] = ti;
	}
	return cnt;
}

static bool torus_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t[4];
	if (!torus_roots((const struct torus *)o, r, tmin, tmax, t))
		return false;
	h->t = t[0];
	h->part = 0;
	return true;
}

static int torus_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[4];
	int n = torus_roots((const struct torus *)o, r, tmin, tmax, t);
	return object_hits_from_roots(o, t, n, out, max);
}

/* POV-Ray's test (checked against povray's inside()): within the minor
 * radius of the major circle, the surface included. */
static bool torus_inside(const struct object *o, vec3 p)
{
	const struct torus *T = (const struct torus *)o;
	return hypot(hypot(p.x, p.z) - T->R, p.y) <= T->r;
}

/* The gradient's direction of the quartic: away from the nearest point of
 * the major circle on the ordinary (apple) surface; towards the far point
 * on the inner lemon of a spindle torus, where that point is the one at
 * distance r. */
static vec3 torus_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct torus *T = (const struct torus *)o;
	(void)h;
	double rho = hypot(p.x, p.z);
	if (!(rho > 0))
		return v3(0, p.y < 0 ? -1 : 1, 0); /* on the axis: a pole */
	double cx = T->R * p.x / rho, cz = T->R * p.z / rho;
	vec3 near = v3(p.x - cx, p.y, p.z - cz), far = v3(p.x + cx, p.y, p.z + cz);
	vec3 n = near;
	if (fabs(v3_len(far) - T->r) < fabs(v3_len(near) - T->r))
		n = v3_neg(far);
	if (n.x == 0 && n.y == 0 && n.z == 0)
		return v3(0, 1, 0);
	return n;
}

static struct aabb torus_bounds(const struct object *o)
{
	const struct torus *T = (const struct torus *)o;
	double e = T->R + T->r;
	return (struct aabb){v3(-e, -T->r, -e), v3(e, T->r, e)};
}

/* POV-Ray's uv_mapping for the torus, measured by rendering: u runs once
 * around the y axis from the -x direction (u = 0) through +z (u = 1/4) and
 * +x (1/2); v runs once around the tube from the inner equator (v = 0)
 * through the bottom (1/4), the outer equator (1/2) and the top (3/4). */
static bool torus_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	const struct torus *T = (const struct torus *)o;
	(void)h;
	uv[0] = 0.5 - atan2(p.z, p.x) / TWO_PI;
	uv[1] = 0.5 + atan2(p.y, hypot(p.x, p.z) - T->R) / TWO_PI;
	return true;
}

static struct object *torus_copy(const struct object *o)
{
	struct torus *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct torus *)o;
	return &c->base;
}

static const struct object_ops torus_ops = {
	.name = "torus",
	.intersect = torus_intersect,
	.all_hits = torus_all_hits,
	.inside = torus_inside,
	.normal = torus_normal,
	.bounds = torus_bounds,
	.uv = torus_uv,
	.copy = torus_copy,
};

struct object *torus_new(double major, double minor, bool sturm, struct srcpos pos)
{
	struct torus *T = calloc(1, sizeof *T);
	if (!T) abort();
	object_init(&T->base, &torus_ops, pos);
	T->R = fabs(major);
	T->r = fabs(minor);
	T->sturm = sturm;
	return &T->base;
}

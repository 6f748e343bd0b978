/* sphere.c: sphere { center, radius }. */
#include "geom/shapes.h"

#include <stdlib.h>

struct sphere {
	struct object base;
	vec3 center;
	double radius, r2;
	bool exact;        /* every transform so far was `simple` (see exact_box) */
	struct aabb box0;  /* !exact: the world box when the first other transform came */
	mat4 inv0;         /* !exact: the inverse transform at that moment */
};

/* Both crossings of the ray with the sphere, or 0. The discriminant is
 * formed from the ray's closest approach to the centre (r^2 - d^2), which
 * keeps its precision for distant spheres and grazing rays alike, and the
 * near root comes from q so that nothing cancels. */
static int roots(const struct sphere *s, const struct ray *r, double t[2])
{
	vec3 oc = v3_sub(r->org, s->center);
	double a = v3_dot(r->dir, r->dir);
	if (a == 0)
		return 0;
	double ia = 1.0 / a; /* one division, started before b is known */
	double b = v3_dot(oc, r->dir);                  /* half the usual b */
	vec3 perp = v3_madd(oc, r->dir, -b * ia);        /* oc minus its along-ray part */
	double disc = a * (s->r2 - v3_dot(perp, perp));  /* (b^2 - a c) computed stably */
	if (disc < 0)
		return 0;
	double c = v3_dot(oc, oc) - s->r2;
	double q = -(b + copysign(sqrt(disc), b));
	if (q == 0) {
		t[0] = t[1] = 0;
		return 2;
	}
	double t0 = q * ia, t1 = c / q;
	t[0] = fmin(t0, t1);
	t[1] = fmax(t0, t1);
	return 2;
}

static bool sphere_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct sphere *s = (const struct sphere *)o;
	double t[2];
	if (!roots(s, r, t))
		return false;
	for (int i = 0; i < 2; i++)
		if (t[i] > tmin && t[i] < tmax) {
			h->t = t[i];
			h->part = i;
			return true;
		}
	return false;
}

static int sphere_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	const struct sphere *s = (const struct sphere *)o;
	double t[2];
	int n = 0;
	if (!roots(s, r, t))
		return 0;
	for (int i = 0; i < 2 && n < max; i++)
		if (t[i] > tmin && t[i] < tmax) {
			out[n].t = t[i];
			out[n].part = i;
			out[n].obj = o;
			n++;
		}
	return n;
}

static bool sphere_inside(const struct object *o, vec3 p)
{
	const struct sphere *s = (const struct sphere *)o;
	vec3 d = v3_sub(p, s->center);
	return v3_dot(d, d) < s->r2;
}

static vec3 sphere_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct sphere *s = (const struct sphere *)o;
	return v3_sub(p, s->center);
}

static struct aabb sphere_bounds(const struct object *o)
{
	const struct sphere *s = (const struct sphere *)o;
	vec3 r = v3(s->radius, s->radius, s->radius);
	struct aabb b = {v3_sub(s->center, r), v3_add(s->center, r)};
	return b;
}

/* POV-Ray moves a sphere's centre and radius for each translate, rotate
 * and scale by equal factors until the first other transform (a scale by
 * unequal factors, a matrix, a transform block or identifier); from then
 * on it keeps a transform, and its box is the box it had at that moment
 * moved by the transforms since (measured with min_extent/max_extent:
 * sphere { <1,0,0>, 1 rotate 45*y } gives x in [-0.292893, 1.707107];
 * with `transform { rotate 45*y }` instead, [-0.707107, 2.121320]; and
 * `rotate 45*y scale <1,2,3>` gives z in [-5.121321, 0.878679]). */
static struct aabb exact_box(const struct sphere *s)
{
	const struct object *o = &s->base;
	if (!o->has_xf)
		return sphere_bounds(o);
	const mat4 *m = &o->xf.fwd;
	/* A simple transform scales every direction by the same factor. */
	double k = s->radius * sqrt(m->m[0][0] * m->m[0][0] + m->m[1][0] * m->m[1][0] + m->m[2][0] * m->m[2][0]);
	vec3 c = mat_point(m, s->center), r = v3(k, k, k);
	struct aabb b = {v3_sub(c, r), v3_add(c, r)};
	return b;
}

static void sphere_transform_bounds(struct object *o, const struct xform *t)
{
	struct sphere *s = (struct sphere *)o;
	if (s->exact && !t->simple) {
		s->box0 = exact_box(s);
		s->inv0 = o->xf.inv;
		s->exact = false;
	}
}

static struct aabb sphere_world_bounds(const struct object *o)
{
	const struct sphere *s = (const struct sphere *)o;
	if (s->exact)
		return exact_box(s);
	mat4 since = mat_mul(&o->xf.fwd, &s->inv0); /* the transforms after box0 was taken */
	return mat_bounds(&since, s->box0);
}

/* POV-Ray's spherical uv (measured against POV-Ray 3.7 renders): with d
 * the point relative to the centre, u = atan2(d.z, d.x) / 2pi taken into
 * [0,1) -- 0 on the +x side, rising through +z (0.25), -x (0.5) and -z
 * (0.75), so the seam is the half-plane z = 0, x > 0 -- and
 * v = 1/2 + latitude/pi, 0 at the -y pole and 1 at the +y pole. atan2 of
 * the height over the horizontal distance gives the latitude without
 * dividing by the radius; at the poles (and the centre) u is 0. */
static bool sphere_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	const struct sphere *s = (const struct sphere *)o;
	static const double TWO_PI = 6.28318530717958647692, PI = 3.14159265358979323846;
	(void)h;
	vec3 d = v3_sub(p, s->center);
	double u = atan2(d.z, d.x) / TWO_PI;
	if (u < 0)
		u += 1;
	if (!(u < 1)) /* -tiny + 1 rounds to 1: that is the seam, u = 0 */
		u = 0;
	uv[0] = u;
	uv[1] = 0.5 + atan2(d.y, hypot(d.x, d.z)) / PI;
	return true;
}

static struct object *sphere_copy(const struct object *o)
{
	struct sphere *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct sphere *)o;
	return &c->base;
}

static const struct object_ops sphere_ops = {
	.name = "sphere",
	.intersect = sphere_intersect,
	.all_hits = sphere_all_hits,
	.inside = sphere_inside,
	.normal = sphere_normal,
	.bounds = sphere_bounds,
	.transform_bounds = sphere_transform_bounds,
	.world_bounds = sphere_world_bounds,
	.uv = sphere_uv,
	.copy = sphere_copy,
};

struct object *sphere_new(vec3 center, double radius, struct srcpos pos)
{
	/* Every field is written (object_init writes the whole header). */
	struct sphere *s = malloc(sizeof *s);
	if (!s) abort();
	object_init(&s->base, &sphere_ops, pos);
	s->center = center;
	s->radius = fabs(radius);
	s->r2 = radius * radius;
	s->exact = true;
	return &s->base;
}

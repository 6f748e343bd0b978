/* disc.c: disc { center, normal, radius [, hole_radius] }, a flat ring
 * without thickness. Its inside, as POV-Ray defines it, is that of the
 * plane holding it: the side the normal points away from, not limited by
 * the radius. */
#include "geom/shapes.h"
#include "geom/frame.h"

#include <stdlib.h>

struct disc {
	struct object base;
	vec3 c;        /* centre */
	vec3 n;        /* unit normal */
	double radius; /* outer radius, >= 0 */
	double r2, h2; /* squared outer and hole radii */
};

/* The crossing with the disc's plane if it lies on the ring
 * (hole <= distance from the centre <= radius, both edges included). A ray
 * parallel to the plane never crosses it. */
static bool disc_hit(const struct disc *s, const struct ray *r, double *t)
{
	double dn = v3_dot(r->dir, s->n);
	if (dn == 0)
		return false;
	vec3 oc = v3_sub(r->org, s->c);
	double tt = -v3_dot(oc, s->n) / dn;
	if (!isfinite(tt))
		return false;
	vec3 q = v3_madd(oc, r->dir, tt);
	double d2 = v3_dot(q, q);
	if (d2 > s->r2 || d2 < s->h2)
		return false;
	*t = tt;
	return true;
}

static bool disc_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t;
	if (!disc_hit((const struct disc *)o, r, &t) || !(t > tmin && t < tmax))
		return false;
	h->t = t;
	h->part = 0;
	return true;
}

static int disc_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	if (max < 1 || !disc_intersect(o, r, tmin, tmax, out))
		return 0;
	out->obj = o;
	return 1;
}

static bool disc_inside(const struct object *o, vec3 p)
{
	const struct disc *s = (const struct disc *)o;
	return v3_dot(v3_sub(p, s->c), s->n) < 0;
}

static vec3 disc_normal(const struct object *o, vec3 p, const struct hit *h)
{
	return ((const struct disc *)o)->n;
}

/* POV-Ray's box, measured with min_extent/max_extent: the box of
 * [-r,r]^2 x [-0.001,0.001] carried to the disc by the frame that takes z
 * to minus the normal (frame.h), and then by the object's transform as
 * one matrix. So disc { <1,2,3>, <1,2,3>, 1 } reaches x in [-0.039911,
 * 2.039911] (the ring itself only [0.036, 1.964]), and disc { 0, y, 1 } is
 * 0.002 thick. This is that map, from [-1,1]^3. */
static mat4 disc_frame(const struct disc *s)
{
	return geom_axis_frame(v3_neg(s->n), s->radius, s->radius, 0.001, s->c);
}

static const struct aabb unit_box = {{-1, -1, -1}, {1, 1, 1}};

static struct aabb disc_bounds(const struct object *o)
{
	mat4 f = disc_frame((const struct disc *)o);
	return mat_bounds(&f, unit_box);
}

static struct aabb disc_world_bounds(const struct object *o)
{
	mat4 f = disc_frame((const struct disc *)o);
	if (o->has_xf)
		f = mat_mul(&o->xf.fwd, &f);
	return mat_bounds(&f, unit_box);
}

static struct object *disc_copy(const struct object *o)
{
	struct disc *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct disc *)o;
	return &c->base;
}

static const struct object_ops disc_ops = {
	.name = "disc",
	.intersect = disc_intersect,
	.all_hits = disc_all_hits,
	.inside = disc_inside,
	.normal = disc_normal,
	.bounds = disc_bounds,
	.world_bounds = disc_world_bounds,
	.copy = disc_copy,
};

/* Negative radii count by their size; a hole at least as large as the
 * disc, or a zero radius, leaves nothing to hit (the inside is still the
 * plane's); a zero normal becomes +y. */
struct object *disc_new(vec3 center, vec3 normal, double radius, double hole, struct srcpos pos)
{
	struct disc *s = calloc(1, sizeof *s);
	if (!s) abort();
	object_init(&s->base, &disc_ops, pos);
	double len = v3_len(normal);
	s->c = center;
	s->n = len > 0 && isfinite(len) ? v3_scale(normal, 1.0 / len) : v3(0, 1, 0);
	s->radius = fabs(radius);
	s->r2 = radius * radius;
	s->h2 = hole * hole;
	if (s->h2 >= s->r2)
		s->r2 = -1; /* no ring left (also a zero radius): never hit */
	return &s->base;
}

/* plane.c: plane { normal, distance }, an infinite half-space whose inside
 * is the side the normal points away from. */
#include "geom/shapes.h"

#include <math.h>
#include <stdlib.h>

struct plane {
	struct object base;
	vec3 n;      /* unit normal */
	double d;    /* dot(p, n) = d on the surface */
};

static bool plane_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct plane *p = (const struct plane *)o;
	double dn = v3_dot(r->dir, p->n);
	if (dn == 0)
		return false; /* parallel: never crosses (lying in it counts as no hit) */
	/* Multiplied by the reciprocal, as box.c's slab test does: a plane
	 * and a box face that coincide then give the same t to the bit, and
	 * the tie goes the same way on every ray (no speckles where a box
	 * stands on a plane). */
	double t = (p->d - v3_dot(r->org, p->n)) * (1.0 / dn);
	if (!(t > tmin && t < tmax))
		return false;
	h->t = t;
	h->part = 0;
	return true;
}

static int plane_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	if (max < 1 || !plane_intersect(o, r, tmin, tmax, out))
		return 0;
	out->obj = o;
	return 1;
}

static bool plane_inside(const struct object *o, vec3 q)
{
	const struct plane *p = (const struct plane *)o;
	/* Points on the plane, and up to 1e-10 outside it, are inside, as in
	 * POV-Ray (measured with inside(): 1e-11 above is inside, 1e-9 not). */
	return v3_dot(q, p->n) - p->d < 1e-10;
}

static vec3 plane_normal(const struct object *o, vec3 q, const struct hit *h)
{
	return ((const struct plane *)o)->n;
}

/* The half-space's box: infinite, except for a plane whose normal lies
 * along an axis (the other components below 1e-10, as POV-Ray judges it:
 * a normal <1e-10, 1, 0> is not axis-aligned, <1e-11, 1, 0> is), where the
 * inside side of the plane is bounded on that axis. POV-Ray's min_extent
 * still reports a lone plane as infinite, but an intersection cuts its
 * box with it. `flip` gives the other half-space (the inverse plane). */
static struct aabb half_space_box(const struct plane *p, bool flip)
{
	struct aabb b = {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
	double n[3] = {p->n.x, p->n.y, p->n.z};
	int axis = -1, small = 0;
	for (int a = 0; a < 3; a++) {
		if (fabs(n[a]) < 1e-10)
			small++;
		else
			axis = a;
	}
	if (small != 2)
		return b;
	/* inside: n[axis] * x < d, or > d for the inverse */
	double x = p->d / n[axis];
	bool below = (n[axis] > 0) != flip;
	vec3 *side = below ? &b.hi : &b.lo;
	if (axis == 0) side->x = x;
	else if (axis == 1) side->y = x;
	else side->z = x;
	return b;
}

static struct aabb plane_bounds(const struct object *o)
{
	return half_space_box((const struct plane *)o, false);
}

static struct aabb plane_inverse_bounds(const struct object *o)
{
	return half_space_box((const struct plane *)o, true);
}

/* A transformed plane is still a plane: its normal turned by the inverse
 * transpose and made unit, its distance that of a point of it moved. As
 * POV-Ray keeps it, so that inside() measures its 1e-10 in world units;
 * and a test no longer moves each ray into object space, nor its normal
 * back out. At prepare, when no transform comes after. */
static void plane_prepare(struct object *o)
{
	struct plane *p = (struct plane *)o;
	if (!o->has_xf)
		return;
	vec3 n = mat_normal(&o->xf.inv, p->n);
	double len = v3_len(n);
	if (!(len > 0 && len < INFINITY))
		return; /* kept as it is */
	vec3 on = mat_point(&o->xf.fwd, v3_scale(p->n, p->d));
	p->n = v3_scale(n, 1.0 / len);
	p->d = v3_dot(on, p->n);
	o->xf = xform_identity();
	o->has_xf = false;
}

static struct object *plane_copy(const struct object *o)
{
	struct plane *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct plane *)o;
	return &c->base;
}

static const struct object_ops plane_ops = {
	.name = "plane",
	.intersect = plane_intersect,
	.all_hits = plane_all_hits,
	.inside = plane_inside,
	.normal = plane_normal,
	.bounds = plane_bounds,
	.inverse_bounds = plane_inverse_bounds,
	.prepare = plane_prepare,
	.copy = plane_copy,
};

struct object *plane_new(vec3 normal, double distance, struct srcpos pos)
{
	struct plane *p = calloc(1, sizeof *p);
	if (!p) abort();
	object_init(&p->base, &plane_ops, pos);
	double len = v3_len(normal);
	p->n = len > 0 ? v3_scale(normal, 1.0 / len) : v3(0, 1, 0);
	p->d = distance;
	return &p->base;
}

/* object.c: the shape-independent half of every object (see object.h). */
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* How many surfaces a clipped object may offer along one ray before the
 * search gives up: a guard against endless loops on degenerate input,
 * far above what any real shape produces. */
enum { CLIP_MAX_CROSSINGS = 100000 };

void object_init(struct object *o, const struct object_ops *ops, struct srcpos pos)
{
	/* The whole header from a template (a scene may make millions of
	 * objects): so a primitive allocated without clearing is complete. */
	static const struct object tmpl = {
		.xf = {.fwd = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}},
		       .inv = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}},
		.bounds = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}},
	};
	*o = tmpl;
	o->ops = ops;
	o->pos = pos;
}

void object_transform(struct object *o, const struct xform *t)
{
	struct object **kids;
	if (o->ops->transform_bounds)
		o->ops->transform_bounds(o, t);
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			object_transform(kids[i], t);
	} else {
		o->xf = xform_compose(t, &o->xf);
		o->has_xf = !mat_is_identity(&o->xf.fwd);
	}
	if (o->clip)
		object_transform(o->clip, t);
	if (o->bound && o->bound != o->clip)
		object_transform(o->bound, t);
}

void object_transform_textures(struct object *o, const struct xform *t)
{
	if (o->tex)
		o->tex = texture_transform(o->tex, t);
	if (o->ops->transform_textures)
		o->ops->transform_textures(o, t);
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			object_transform_textures(kids[i], t);
	}
}

void object_set_flags(struct object *o, unsigned flags)
{
	o->flags |= flags;
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			object_set_flags(kids[i], flags);
	}
}

void object_fill_texture(struct object *o, struct texture *t)
{
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			object_fill_texture(kids[i], t);
	} else if (!o->tex) {
		o->tex = texture_ref(t);
	}
}

void object_fill_interior(struct object *o, struct interior *in)
{
	struct object **kids;
	if (!o->ops->children)
		return;
	size_t n = o->ops->children(o, &kids);
	for (size_t i = 0; i < n; i++) {
		if (kids[i]->ops->children)
			object_fill_interior(kids[i], in);
		else if (!kids[i]->interior)
			kids[i]->interior = interior_ref(in);
	}
}

void object_prepare(struct object *o)
{
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			object_prepare(kids[i]);
	}
	if (o->clip)
		object_prepare(o->clip);
	if (o->bound && o->bound != o->clip)
		object_prepare(o->bound);
	o->loose = (o->flags & OBJ_INVERSE) || (o->bound && o->bound != o->clip) || (o->clip && o->clip->loose);
	if (o->ops->prepare)
		o->ops->prepare(o); /* a CSG adds its children's looseness */
	o->bounds = object_world_bounds(o);
}

struct object *object_copy(const struct object *o)
{
	struct object *c = o->ops->copy(o);
	texture_ref(c->tex);
	interior_ref(c->interior);
	c->clip = o->clip ? object_copy(o->clip) : NULL;
	if (o->bound == o->clip)
		c->bound = c->clip;
	else
		c->bound = o->bound ? object_copy(o->bound) : NULL;
	return c;
}

void object_free(struct object *o)
{
	if (!o) return;
	texture_unref(o->tex);
	interior_unref(o->interior);
	if (o->bound != o->clip)
		object_free(o->bound);
	object_free(o->clip);
	if (o->ops->destroy)
		o->ops->destroy(o);
	free(o);
}

int object_hits_from_roots(const struct object *o, const double *t, int n, struct hit *out, int max)
{
	if (n > max)
		n = max;
	for (int i = 0; i < n; i++) {
		out[i].t = t[i];
		out[i].part = i;
		out[i].obj = o;
	}
	return n;
}

/* The closest hit of the object's own surface, ignoring clip and bound. */
static bool surface_hit(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	h->obj = o; /* CSG replaces it with the leaf it hit */
	h->inverted = false; /* a CSG's child sets it for the path below */
	bool found;
	if (!o->has_xf)
		found = o->ops->intersect(o, r, tmin, tmax, h);
	else {
		struct ray lr = {mat_point(&o->xf.inv, r->org), mat_dir(&o->xf.inv, r->dir)};
		found = o->ops->intersect(o, &lr, tmin, tmax, h);
	}
	if (found && (o->flags & OBJ_INVERSE))
		h->inverted = !h->inverted;
	return found;
}

bool object_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	if (o->bound) {
		/* A ray that neither starts inside the bound nor crosses it in the
		 * interval cannot reach the object. */
		struct hit bh;
		vec3 start = v3_madd(r->org, r->dir, tmin);
		if (!object_inside(o->bound, start) && !object_intersect(o->bound, r, tmin, tmax, &bh))
			return false;
	}
	if (!o->clip)
		return surface_hit(o, r, tmin, tmax, h);
	for (int i = 0; i < CLIP_MAX_CROSSINGS; i++) {
		if (!surface_hit(o, r, tmin, tmax, h))
			return false;
		if (object_inside(o->clip, v3_madd(r->org, r->dir, h->t)))
			return true;
		tmin = h->t;
	}
	return false;
}

vec3 object_normal(const struct object *o, vec3 p, const struct hit *h)
{
	if (!o->has_xf)
		return v3_norm(o->ops->normal(o, p, h));
	vec3 lp = mat_point(&o->xf.inv, p);
	vec3 n = o->ops->normal(o, lp, h);
	return v3_norm(mat_normal(&o->xf.inv, n));
}

bool object_inside(const struct object *o, vec3 p)
{
	vec3 lp = o->has_xf ? mat_point(&o->xf.inv, p) : p;
	bool in = o->ops->inside(o, lp);
	if (o->flags & OBJ_INVERSE)
		in = !in;
	if (in && o->clip)
		in = object_inside(o->clip, p);
	return in;
}

static const struct aabb inf_box = {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};

/* The box of m applied to b, where b may be unbounded on some sides (a
 * plane's half-space): each output axis sums the input intervals its row
 * mixes in, skipping zero coefficients, so that a translation, a scale or
 * a rotation by a multiple of 90 degrees keeps the finite sides finite. */
static struct aabb box_transform(const mat4 *m, struct aabb b)
{
	if (aabb_is_finite(b))
		return mat_bounds(m, b);
	double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z}, rl[3], rh[3];
	for (int i = 0; i < 3; i++) {
		rl[i] = rh[i] = m->m[i][3];
		for (int j = 0; j < 3; j++) {
			double c = m->m[i][j];
			if (c == 0)
				continue;
			double a = c * lo[j], z = c * hi[j];
			rl[i] += a < z ? a : z;
			rh[i] += a < z ? z : a;
		}
	}
	return (struct aabb){{rl[0], rl[1], rl[2]}, {rh[0], rh[1], rh[2]}};
}

/* A box's volume, infinite when a side is unbounded (never 0 * inf). */
static double box_volume(struct aabb b)
{
	if (!aabb_is_finite(b))
		return INFINITY;
	vec3 d = v3_sub(b.hi, b.lo);
	return d.x * d.y * d.z;
}

struct aabb object_world_bounds_raw(const struct object *o, bool invert)
{
	struct aabb b = inf_box;
	bool inverse = ((o->flags & OBJ_INVERSE) != 0) != invert;
	if (!inverse || o->ops->inverse_bounds) {
		if (!inverse && o->ops->world_bounds)
			b = o->ops->world_bounds(o);
		else {
			b = inverse ? o->ops->inverse_bounds(o) : o->ops->bounds(o);
			if (o->has_xf)
				b = box_transform(&o->xf.fwd, b);
		}
	}
	/* POV-Ray keeps the smallest by volume of the object's own box and
	 * the boxes of its clip and its bound (it does not cut one with the
	 * other: a sphere clipped by a larger box keeps the sphere's box). */
	const struct object *lim[2] = {o->clip, o->bound};
	double vol = box_volume(b);
	for (int i = 0; i < 2; i++) {
		if (!lim[i])
			continue;
		struct aabb c = object_world_bounds(lim[i]);
		double cv = box_volume(c);
		if (cv < vol) {
			b = c;
			vol = cv;
		}
	}
	return b;
}

struct aabb object_world_bounds(const struct object *o)
{
	/* Measured in POV-Ray: `sphere { 0, 1 inverse }` reports +-1, and a
	 * union with it as a part includes that box; an intersection leaves
	 * such parts out (see csg.c). */
	bool keep = (o->flags & OBJ_INVERSE) && !o->ops->inverse_bounds;
	struct aabb b = object_world_bounds_raw(o, keep);
	/* Unbounded on any axis, or empty (an intersection of disjoint
	 * children): infinite, as POV-Ray's min_extent reports it. */
	if (!aabb_is_finite(b) || b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z)
		return inf_box;
	return b;
}

struct aabb object_box_single(struct aabb b)
{
	double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
	for (int i = 0; i < 3; i++) {
		double l = fmax(fmin(lo[i], 1e10), -1e10), h = fmax(fmin(hi[i], 1e10), -1e10);
		float lf = (float)l;
		lo[i] = lf;
		hi[i] = (float)(lf + (float)(h - l));
	}
	return (struct aabb){{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
}

bool object_ray_meets_box(struct aabb b, const struct ray *r, double tmin, double tmax)
{
	if (!aabb_is_finite(b))
		return true;
	double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
	double org[3] = {r->org.x, r->org.y, r->org.z}, dir[3] = {r->dir.x, r->dir.y, r->dir.z};
	for (int i = 0; i < 3; i++) {
		double m = 1e-9 * (hi[i] - lo[i] + fabs(lo[i]) + fabs(hi[i]));
		double a = lo[i] - m, z = hi[i] + m;
		if (dir[i] == 0) {
			if (org[i] < a || org[i] > z)
				return false;
			continue;
		}
		double t0 = (a - org[i]) / dir[i], t1 = (z - org[i]) / dir[i];
		if (t0 > t1) {
			double t = t0;
			t0 = t1;
			t1 = t;
		}
		tmin = t0 > tmin ? t0 : tmin;
		tmax = t1 < tmax ? t1 : tmax;
		if (tmin > tmax)
			return false;
	}
	return true;
}

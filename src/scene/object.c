/* object.c: the shape-independent half of every object (see object.h). */
#include "scene/object.h"

#include <stdlib.h>
#include <string.h>

void object_init(struct object *o, const struct object_ops *ops, struct srcpos pos)
{
	o->ops = ops;
	o->xf = xform_identity();
	o->has_xf = false;
	o->tex = NULL;
	o->flags = 0;
	o->bounds = aabb_empty();
	o->pos = pos;
	o->id = 0;
}

void object_transform(struct object *o, const struct xform *t)
{
	o->xf = xform_compose(t, &o->xf);
	o->has_xf = !mat_is_identity(&o->xf.fwd);
}

struct object *object_copy(const struct object *o)
{
	struct object *c = o->ops->copy(o);
	texture_ref(c->tex);
	return c;
}

void object_free(struct object *o)
{
	if (!o) return;
	texture_unref(o->tex);
	if (o->ops->destroy)
		o->ops->destroy(o);
	free(o);
}

bool object_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	bool hit;
	if (o->has_xf) {
		struct ray lr = {mat_point(&o->xf.inv, r->org), mat_dir(&o->xf.inv, r->dir)};
		hit = o->ops->intersect(o, &lr, tmin, tmax, h);
	} else {
		hit = o->ops->intersect(o, r, tmin, tmax, h);
	}
	if (hit)
		h->obj = o;
	return hit;
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
	return (o->flags & OBJ_INVERSE) ? !in : in;
}

struct aabb object_world_bounds(const struct object *o)
{
	struct aabb b = o->ops->bounds(o);
	if (!aabb_is_finite(b) || (o->flags & OBJ_INVERSE))
		return (struct aabb){{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
	return o->has_xf ? mat_bounds(&o->xf.fwd, b) : b;
}

/* shapetest.h: ray helpers shared by the unit tests of the primitives.
 * Include after <cmocka.h>, "scene/object.h" and "testutil.h". */
#ifndef LUCENT_SHAPETEST_H
#define LUCENT_SHAPETEST_H

#include <math.h>

static inline struct ray mkray(vec3 org, vec3 dir)
{
	struct ray r = {org, dir};
	return r;
}

/* The closest hit in (tmin, inf), failing the test on a miss; the hit
 * must name o and have a finite t. */
static inline struct hit must_hit(const struct object *o, vec3 org, vec3 dir, double tmin)
{
	struct ray r = mkray(org, dir);
	struct hit h = {.t = -1, .part = -1};
	if (!object_intersect(o, &r, tmin, INFINITY, &h))
		fail_msg("ray <%g,%g,%g> + t<%g,%g,%g> missed the %s", org.x, org.y, org.z, dir.x, dir.y, dir.z,
		         o->ops->name);
	assert_ptr_equal(h.obj, o);
	assert_true(isfinite(h.t));
	return h;
}

static inline bool hits(const struct object *o, vec3 org, vec3 dir, double tmin, double tmax)
{
	struct ray r = mkray(org, dir);
	struct hit h;
	return object_intersect(o, &r, tmin, tmax, &h);
}

/* The world normal at the hit, checked to be unit length. */
static inline vec3 hit_normal(const struct object *o, vec3 org, vec3 dir, const struct hit *h)
{
	vec3 n = object_normal(o, v3_madd(org, dir, h->t), h);
	assert_near(v3_len(n), 1, 1e-15);
	return n;
}

/* The closest hit's point and unit normal, each to match to 1e-9 (values
 * POV-Ray's trace() prints). */
static inline void check_hit(const struct object *o, vec3 org, vec3 dir, vec3 p, vec3 n)
{
	struct hit h = must_hit(o, org, dir, 0);
	vec3 q = v3_madd(org, dir, h.t);
	assert_vec_near(q, p.x, p.y, p.z, 1e-9);
	vec3 m = hit_normal(o, org, dir, &h);
	assert_vec_near(m, n.x, n.y, n.z, 1e-9);
}

/* The world box, to POV-Ray's single precision. */
static inline void check_box(const struct object *o, vec3 lo, vec3 hi)
{
	struct aabb b = object_world_bounds(o);
	assert_vec_near(b.lo, lo.x, lo.y, lo.z, 5e-7);
	assert_vec_near(b.hi, hi.x, hi.y, hi.z, 5e-7);
}

static inline void transform(struct object *o, struct xform t)
{
	object_transform(o, &t);
}

#endif

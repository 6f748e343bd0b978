/* test_quadrics.c: unit tests for the quadric-family primitives: cylinder
 * and cone (src/geom/cylinder.c), disc, quadric and superellipsoid, hit
 * through the shape-independent layer (src/scene/object.h) and compared
 * with analytic answers: hits, misses, tangent and grazing rays, rays
 * starting inside or on the surface, transformed objects, normals, inside
 * tests (as POV-Ray 3.7 answers them) and bounds. The superellipsoid is
 * also checked against dense sampling of its implicit function. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes.h"
#include "scene/object.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* all_hits on an untransformed object. */
static int all(const struct object *o, vec3 org, vec3 dir, double tmin, double tmax, struct hit *out, int max)
{
	struct ray r = mkray(org, dir);
	int n = o->ops->all_hits(o, &r, tmin, tmax, out, max);
	for (int i = 0; i < n; i++) {
		assert_ptr_equal(out[i].obj, o);
		assert_true(isfinite(out[i].t));
		if (i > 0)
			assert_true(out[i].t >= out[i - 1].t);
	}
	return n;
}

/* ---- cylinder ---- */

static void test_cylinder_hit_miss(void **state)
{
	(void)state;
	struct object *c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), 1, false, nopos);
	assert_string_equal(c->ops->name, "cylinder");
	vec3 org = v3(0, 1, -5), dz = v3(0, 0, 1);
	struct hit h = must_hit(c, org, dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(c, org, dz, &h), 0, 0, -1, 0);
	h = must_hit(c, org, dz, 4);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(c, org, dz, &h), 0, 0, 1, 0);
	/* Down the axis: the cap at y = 2, then the base at y = 0. */
	vec3 top = v3(0.5, 5, -0.25), dy = v3(0, -1, 0);
	h = must_hit(c, top, dy, 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(c, top, dy, &h), 0, 1, 0, 0);
	h = must_hit(c, top, dy, 3);
	assert_near(h.t, 5, 0);
	assert_vec_near(hit_normal(c, top, dy, &h), 0, -1, 0, 0);
	/* Parallel to the axis outside the radius, beside it, above it, away. */
	assert_false(hits(c, v3(1.0000001, 5, 0), dy, 0, INFINITY));
	assert_false(hits(c, v3(1.0000001, 1, -5), dz, 0, INFINITY));
	assert_false(hits(c, v3(0, 2.0000001, -5), dz, 0, INFINITY));
	assert_false(hits(c, v3(0, -0.0000001, -5), dz, 0, INFINITY));
	assert_false(hits(c, org, v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(c, org, dz, 0, 4));
	assert_false(hits(c, org, v3(0, 0, 0), 0, INFINITY));
	/* An oblique ray through the rim edge at <-1,2,0> (side and cap meet
	 * there; neither may let it through). */
	h = must_hit(c, v3(-2, 3, 0), v3(1, -1, 0), 0);
	assert_near(h.t, 1, 1e-15);
	/* Oblique through the side: from <-3,1,0> along <1,0.25,0>, x = -1 at
	 * t = 2 (y = 1.5). */
	h = must_hit(c, v3(-3, 1, 0), v3(1, 0.25, 0), 0);
	assert_near(h.t, 2, 0);
	assert_vec_near(hit_normal(c, v3(-3, 1, 0), v3(1, 0.25, 0), &h), -1, 0, 0, 0);
	/* ... and out through the cap: y = 2 at t = 4 (x = 1, on the rim). */
	h = must_hit(c, v3(-3, 1, 0), v3(1, 0.25, 0), 2);
	assert_near(h.t, 4, 0);
	object_free(c);
}

static void test_cylinder_grazing(void **state)
{
	(void)state;
	struct object *c = cylinder_new(v3(0, -1, 0), v3(0, 1, 0), 1, false, nopos);
	vec3 dz = v3(0, 0, 1);
	/* Exactly tangent at x = 1: touches at t = 5. */
	struct hit h = must_hit(c, v3(1, 0, -5), dz, 0);
	assert_near(h.t, 5, 0);
	assert_false(hits(c, v3(1 + 1e-9, 0, -5), dz, 0, INFINITY));
	/* Just inside: the roots 5 -+ sqrt(1 - d^2) to full precision. */
	double d = 1 - 1e-7, half = sqrt((1 - d) * (1 + d));
	h = must_hit(c, v3(d, 0, -5), dz, 0);
	assert_near(h.t, 5 - half, 1e-13);
	h = must_hit(c, v3(d, 0, -5), dz, 5);
	assert_near(h.t, 5 + half, 1e-13);
	vec3 n = hit_normal(c, v3(d, 0, -5), dz, &h);
	assert_near(n.x, d, 1e-12);
	assert_near(n.y, 0, 0);
	/* Far away: the axis at x = 1e5, seen from the origin. */
	object_free(c);
	c = cylinder_new(v3(1e5, 0, -1), v3(1e5, 0, 1), 1, false, nopos);
	h = must_hit(c, v3(0, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 1e5 - sqrt(0.75), 1e-9);
	h = must_hit(c, v3(0, 0.5, 0), v3(1, 0, 0), 1e5);
	assert_near(h.t, 1e5 + sqrt(0.75), 1e-9);
	object_free(c);
}

static void test_cylinder_inside_and_on_surface(void **state)
{
	(void)state;
	struct object *c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), 1, false, nopos);
	/* From inside: one crossing per direction. */
	struct hit h = must_hit(c, v3(0, 1, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 1, 0);
	h = must_hit(c, v3(0, 1, 0), v3(0, 0.5, 0), 0);
	assert_near(h.t, 2, 0);
	assert_vec_near(hit_normal(c, v3(0, 1, 0), v3(0, 0.5, 0), &h), 0, 1, 0, 0);
	/* Starting on the side: t = 0 is excluded. */
	h = must_hit(c, v3(1, 1, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, 2, 0);
	assert_false(hits(c, v3(1, 1, 0), v3(1, 0, 0), 0, INFINITY));
	/* Starting on a cap. */
	h = must_hit(c, v3(0.5, 0, 0), v3(0, 1, 0), 0);
	assert_near(h.t, 2, 0);
	assert_false(hits(c, v3(0.5, 2, 0), v3(0, 1, 0), 0, INFINITY));
	/* Inside is strict, as in POV-Ray. */
	assert_true(object_inside(c, v3(0, 1, 0)));
	assert_true(object_inside(c, v3(0, 1, 0.999)));
	assert_true(object_inside(c, v3(0.7, 1.999, -0.7)));
	assert_false(object_inside(c, v3(0, 0, 0)));
	assert_false(object_inside(c, v3(0, 2.0001, 0)));
	assert_false(object_inside(c, v3(0, -0.5, 0)));
	assert_false(object_inside(c, v3(1.0001, 1, 0)));
	assert_false(object_inside(c, v3(0.8, 1, 0.8)));
	/* all_hits. */
	struct hit out[4];
	assert_int_equal(all(c, v3(0, 1, -5), v3(0, 0, 1), 0, INFINITY, out, 4), 2);
	assert_near(out[0].t, 4, 0);
	assert_near(out[1].t, 6, 0);
	assert_int_equal(all(c, v3(0, 5, 0.5), v3(0, -1, 0), 0, INFINITY, out, 4), 2);
	assert_near(out[0].t, 3, 0);
	assert_near(out[1].t, 5, 0);
	assert_int_not_equal(out[0].part, out[1].part);
	assert_int_equal(all(c, v3(0, 5, 0.5), v3(0, -1, 0), 0, INFINITY, out, 1), 1);
	assert_near(out[0].t, 3, 0);
	assert_int_equal(all(c, v3(0, 5, 0.5), v3(0, -1, 0), 4, INFINITY, out, 4), 1);
	assert_near(out[0].t, 5, 0);
	assert_int_equal(all(c, v3(0, 1, 0), v3(0, 0, 1), 0, INFINITY, out, 4), 1);
	assert_int_equal(all(c, v3(3, 1, 0), v3(0, 0, 1), 0, INFINITY, out, 4), 0);
	/* Bounds. */
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -1, 0, -1, 0);
	assert_vec_near(b.hi, 1, 2, 1, 0);
	/* With no hit record, the normal of the nearest surface. */
	assert_vec_near(object_normal(c, v3(0.2, 1.98, 0.1), NULL), 0, 1, 0, 0);
	assert_vec_near(object_normal(c, v3(0.2, 0.01, 0.1), NULL), 0, -1, 0, 0);
	assert_vec_near(object_normal(c, v3(0, 1, -0.99), NULL), 0, 0, -1, 0);
	object_free(c);
}

static void test_cylinder_open(void **state)
{
	(void)state;
	struct object *c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), 1, true, nopos);
	/* No caps: straight down the inside passes through. */
	assert_false(hits(c, v3(0, 5, 0), v3(0, -1, 0), 0, INFINITY));
	/* The side both ways, and from inside the tube the far wall. */
	struct hit h = must_hit(c, v3(0, 1, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	h = must_hit(c, v3(0, 1, -5), v3(0, 0, 1), 4);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(c, v3(0, 1, -5), v3(0, 0, 1), &h), 0, 0, 1, 0);
	/* Entering through the open end, meeting the wall from inside at
	 * <1,1,0>: the normal is still the outward one. */
	h = must_hit(c, v3(0, 3, 0), v3(0.5, -1, 0), 0);
	assert_near(h.t, 2, 0);
	assert_vec_near(hit_normal(c, v3(0, 3, 0), v3(0.5, -1, 0), &h), 1, 0, 0, 0);
	/* A ray through the open end that misses the wall. */
	assert_false(hits(c, v3(0, 3, 0), v3(0.1, -1, 0), 0, INFINITY));
	/* POV-Ray's inside test treats the open cylinder as closed. */
	assert_true(object_inside(c, v3(0, 1, 0)));
	assert_true(object_inside(c, v3(0, 1, 0.999)));
	assert_false(object_inside(c, v3(0, 3, 0)));
	struct hit out[4];
	assert_int_equal(all(c, v3(0.5, 5, 0), v3(0, -1, 0), 0, INFINITY, out, 4), 0);
	/* With no hit record the normal is always the side's. */
	assert_vec_near(object_normal(c, v3(0.99, 1.999, 0), NULL), 1, 0, 0, 1e-15);
	object_free(c);
}

static void test_cylinder_oblique_and_transformed(void **state)
{
	(void)state;
	/* Axis along <0.6,0.8,0>, length 5; across it n = <-0.8,0.6,0>. */
	struct object *c = cylinder_new(v3(0, 0, 0), v3(3, 4, 0), 1, false, nopos);
	vec3 n = v3(-0.8, 0.6, 0), mid = v3(1.5, 2, 0);
	vec3 org = v3_madd(mid, n, 5);
	struct hit h = must_hit(c, org, v3_neg(n), 0);
	assert_near(h.t, 4, 1e-14);
	vec3 hn = hit_normal(c, org, v3_neg(n), &h);
	assert_vec_near(hn, n.x, n.y, n.z, 1e-14);
	/* Along the axis from before the base. */
	h = must_hit(c, v3(-0.6, -0.8, 0), v3(0.6, 0.8, 0), 0);
	assert_near(h.t, 1, 1e-14);
	assert_vec_near(hit_normal(c, v3(-0.6, -0.8, 0), v3(0.6, 0.8, 0), &h), -0.6, -0.8, 0, 1e-14);
	h = must_hit(c, v3(-0.6, -0.8, 0), v3(0.6, 0.8, 0), 1.5);
	assert_near(h.t, 6, 1e-14);
	/* Bounds: POV-Ray's (min_extent <-1.12,-0.84,-1.4>, max_extent
	 * <4.12,4.84,1.4>): the box of [-1,1]^2 x [0,5] carried by the rotation
	 * taking z to -w, whose x and y images are <0.64,-0.48,0.6> and
	 * <-0.48,0.36,0.8> (see cylinder.c). */
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -1.12, -0.84, -1.4, 1e-15);
	assert_vec_near(b.hi, 4.12, 4.84, 1.4, 1e-15);
	assert_true(object_inside(c, mid));
	assert_false(object_inside(c, v3_madd(mid, n, 1.01)));
	assert_true(object_inside(c, v3_madd(mid, n, 0.99)));
	object_free(c);

	/* scale <2,1,1> then translate: an elliptic cylinder around x = 10. */
	c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), 1, false, nopos);
	transform(c, xform_scale(v3(2, 1, 1)));
	transform(c, xform_translate(v3(10, 0, 0)));
	h = must_hit(c, v3(0, 1, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 8, 0);
	assert_vec_near(hit_normal(c, v3(0, 1, 0), v3(1, 0, 0), &h), -1, 0, 0, 0);
	h = must_hit(c, v3(10, 1, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	h = must_hit(c, v3(11, 7, 0), v3(0, -2, 0), 0);
	assert_near(h.t, 2.5, 0);
	assert_vec_near(hit_normal(c, v3(11, 7, 0), v3(0, -2, 0), &h), 0, 1, 0, 0);
	assert_true(object_inside(c, v3(11.9, 1, 0)));
	assert_false(object_inside(c, v3(10, 1, 1.1)));
	b = object_world_bounds(c);
	assert_vec_near(b.lo, 8, 0, -1, 0);
	assert_vec_near(b.hi, 12, 2, 1, 0);
	object_free(c);
}

static void test_cylinder_degenerate(void **state)
{
	(void)state;
	/* base == cap (POV-Ray's parser refuses it): nothing, but no NaN. */
	struct object *c = cylinder_new(v3(1, 2, 3), v3(1, 2, 3), 1, false, nopos);
	assert_false(hits(c, v3(1, 2, -5), v3(0, 0, 1), -INFINITY, INFINITY));
	assert_false(hits(c, v3(1, -5, 3), v3(0, 1, 0), -INFINITY, INFINITY));
	assert_false(object_inside(c, v3(1, 2, 3)));
	struct aabb b = object_world_bounds(c);
	assert_true(aabb_is_finite(b));
	assert_vec_near(b.lo, 1, 2, 3, 0);
	assert_vec_near(b.hi, 1, 2, 3, 0);
	object_free(c);
	/* Zero radius. */
	c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), 0, false, nopos);
	assert_false(hits(c, v3(0, 1, -5), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(c, v3(0, 5, 0), v3(0, -1, 0), 0, INFINITY));
	assert_false(object_inside(c, v3(0, 1, 0)));
	b = object_world_bounds(c);
	assert_vec_near(b.lo, 0, 0, 0, 0);
	assert_vec_near(b.hi, 0, 2, 0, 0);
	object_free(c);
	/* A negative radius is its size. */
	c = cylinder_new(v3(0, 0, 0), v3(0, 2, 0), -1, false, nopos);
	struct hit h = must_hit(c, v3(0, 1, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	h = must_hit(c, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_true(object_inside(c, v3(0, 1, 0.5)));
	b = object_world_bounds(c);
	assert_vec_near(b.lo, -1, 0, -1, 0);
	object_free(c);
}

/* ---- cone ---- */

static void test_cone_pointed(void **state)
{
	(void)state;
	/* Radius 1 at y = 0 narrowing to a point at y = 2: rho = 1 - y/2. */
	struct object *c = cone_new(v3(0, 0, 0), 1, v3(0, 2, 0), 0, false, nopos);
	assert_string_equal(c->ops->name, "cone");
	vec3 org = v3(-5, 1, 0), dx = v3(1, 0, 0);
	struct hit h = must_hit(c, org, dx, 0);
	assert_near(h.t, 4.5, 0);
	vec3 ex = v3_norm(v3(-2, 1, 0)); /* the gradient (x, -rho k, z) ~ (-0.5, 0.25, 0) */
	assert_vec_near(hit_normal(c, org, dx, &h), ex.x, ex.y, ex.z, 1e-15);
	h = must_hit(c, org, dx, 4.5);
	assert_near(h.t, 5.5, 0);
	/* Into the base from below. */
	h = must_hit(c, v3(0.2, -3, 0.1), v3(0, 1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(c, v3(0.2, -3, 0.1), v3(0, 1, 0), &h), 0, -1, 0, 0);
	/* Down the axis: touches the apex (t = 3) with a finite normal, then
	 * the base (t = 5). */
	h = must_hit(c, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 1e-15);
	assert_vec_near(hit_normal(c, v3(0, 5, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	h = must_hit(c, v3(0, 5, 0), v3(0, -1, 0), 3.5);
	assert_near(h.t, 5, 0);
	/* Past the apex, and beside the narrowing part. */
	assert_false(hits(c, v3(-5, 2.001, 0), dx, 0, INFINITY));
	assert_false(hits(c, v3(-5, 1.5, 0.26), dx, 0, INFINITY));
	assert_true(hits(c, v3(-5, 1.5, 0.24), dx, 0, INFINITY));
	/* Parallel to a generator (the side's quadratic is linear): the ray
	 * <0.5,-1,0> + t<-1,2,0> enters the base at t = 0.5 and leaves through
	 * the side at t = 1, <-0.5, 1, 0>. */
	vec3 go = v3(0.5, -1, 0), gd = v3(-1, 2, 0);
	h = must_hit(c, go, gd, 0);
	assert_near(h.t, 0.5, 0);
	h = must_hit(c, go, gd, 0.5);
	assert_near(h.t, 1, 1e-15);
	ex = v3_norm(v3(-2, 1, 0));
	assert_vec_near(hit_normal(c, go, gd, &h), ex.x, ex.y, ex.z, 1e-15);
	/* Inside. */
	assert_true(object_inside(c, v3(0, 1, 0.45)));
	assert_false(object_inside(c, v3(0, 1, 0.55)));
	assert_true(object_inside(c, v3(0, 1.99, 0)));
	assert_false(object_inside(c, v3(0, 2.01, 0)));
	/* Bounds: the base disc and the apex. */
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -1, 0, -1, 0);
	assert_vec_near(b.hi, 1, 2, 1, 0);
	object_free(c);
}

static void test_cone_frustum(void **state)
{
	(void)state;
	/* Radius 2 at y = 0, 1 at y = 1: rho = 2 - y; the gradient is
	 * (x, rho, z). */
	struct object *c = cone_new(v3(0, 0, 0), 2, v3(0, 1, 0), 1, false, nopos);
	struct hit h = must_hit(c, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 3.5, 0);
	vec3 ex = v3_norm(v3(-1.5, 1.5, 0));
	assert_vec_near(hit_normal(c, v3(-5, 0.5, 0), v3(1, 0, 0), &h), ex.x, ex.y, ex.z, 1e-15);
	h = must_hit(c, v3(0, 4, 0.9), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(c, v3(0, 4, 0.9), v3(0, -1, 0), &h), 0, 1, 0, 0);
	/* Outside the top but over the base: down onto the slanted side at
	 * rho = 1.5, y = 0.5. */
	h = must_hit(c, v3(0, 4, 1.5), v3(0, -1, 0), 0);
	assert_near(h.t, 3.5, 0);
	/* The same cone given cap first: the same solid. */
	struct object *c2 = cone_new(v3(0, 1, 0), 1, v3(0, 0, 0), 2, false, nopos);
	struct hit h2 = must_hit(c2, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h2.t, 3.5, 0);
	assert_vec_near(hit_normal(c2, v3(-5, 0.5, 0), v3(1, 0, 0), &h2), ex.x, ex.y, ex.z, 1e-15);
	h2 = must_hit(c2, v3(0, 4, 0.9), v3(0, -1, 0), 0);
	assert_near(h2.t, 3, 0);
	assert_vec_near(hit_normal(c2, v3(0, 4, 0.9), v3(0, -1, 0), &h2), 0, 1, 0, 0);
	object_free(c2);
	/* Equal radii: a cylinder, by either constructor. */
	struct object *cc = cone_new(v3(0, 0, 0), 1, v3(0, 2, 0), 1, false, nopos);
	h = must_hit(cc, v3(0, 1, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(cc, v3(0, 1, -5), v3(0, 0, 1), &h), 0, 0, -1, 0);
	object_free(cc);
	/* Open: no caps, inside still closed. */
	struct object *co = cone_new(v3(0, 0, 0), 2, v3(0, 1, 0), 1, true, nopos);
	assert_false(hits(co, v3(0, 4, 0.9), v3(0, -1, 0), 0, INFINITY));
	assert_true(object_inside(co, v3(0, 0.5, 1.4)));
	assert_false(object_inside(co, v3(0, 0.5, 1.6)));
	h = must_hit(co, v3(0, 4, 1.5), v3(0, -1, 0), 0);
	assert_near(h.t, 3.5, 0);
	object_free(co);
	/* Bounds: the larger disc. */
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -2, 0, -2, 0);
	assert_vec_near(b.hi, 2, 1, 2, 0);
	object_free(c);
}

static void test_cone_signed_radii(void **state)
{
	(void)state;
	/* Radii of opposite signs: two cones meeting at a point, as POV-Ray
	 * draws and tests it (inside(), POV-Ray 3.7). */
	struct object *c = cone_new(v3(0, 0, 0), -1, v3(0, 2, 0), 1, false, nopos);
	assert_false(object_inside(c, v3(0, 1, 0)));
	assert_true(object_inside(c, v3(0, 0.2, 0.5)));
	assert_true(object_inside(c, v3(0, 1.8, 0.5)));
	assert_false(object_inside(c, v3(0, 0.2, 0.9)));
	/* rho = y - 1: across at y = 0.5 the surface is at |x| = 0.5. */
	struct hit h = must_hit(c, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4.5, 0);
	/* Down the axis: the cap, the waist point (touched twice), the base. */
	struct hit out[8];
	int n = all(c, v3(0, 3, 0), v3(0, -1, 0), 0, INFINITY, out, 8);
	assert_int_equal(n, 4);
	assert_near(out[0].t, 1, 0);
	assert_near(out[1].t, 2, 0);
	assert_near(out[2].t, 2, 0);
	assert_near(out[3].t, 3, 0);
	object_free(c);
	/* Both negative: the same as both positive. */
	c = cone_new(v3(0, 0, 0), -2, v3(0, 1, 0), -1, false, nopos);
	h = must_hit(c, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 3.5, 0);
	object_free(c);
}

static void test_cone_transformed_and_degenerate(void **state)
{
	(void)state;
	/* A cone along z from z = 0 (r 1) to z = 4 (r 0), turned 90 about y
	 * (z goes to x) and moved up 1: its axis runs along +x at y = 1. */
	struct object *c = cone_new(v3(0, 0, 0), 1, v3(0, 0, 4), 0, false, nopos);
	transform(c, xform_rotate(v3(0, 90, 0)));
	transform(c, xform_translate(v3(0, 1, 0)));
	/* At x = 2 the radius is 0.5. */
	struct hit h = must_hit(c, v3(2, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3.5, 1e-14);
	vec3 n = hit_normal(c, v3(2, 5, 0), v3(0, -1, 0), &h);
	vec3 ex = v3_norm(v3(0.25, 1, 0)); /* (-rho k along the axis, radial) */
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-14);
	h = must_hit(c, v3(-3, 1.2, 0.3), v3(1, 0, 0), 0);
	assert_near(h.t, 3, 1e-14);
	assert_vec_near(hit_normal(c, v3(-3, 1.2, 0.3), v3(1, 0, 0), &h), -1, 0, 0, 1e-14);
	assert_true(object_inside(c, v3(1, 1, 0)));
	assert_false(object_inside(c, v3(3, 1, 0.5)));
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, 0, 0, -1, 1e-15);
	assert_vec_near(b.hi, 4, 2, 1, 1e-15);
	/* A copy is the same cone. */
	struct object *cp = object_copy(c);
	h = must_hit(cp, v3(2, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3.5, 1e-14);
	object_free(cp);
	object_free(c);
	/* Degenerate: both radii 0, and base == cap. */
	c = cone_new(v3(0, 0, 0), 0, v3(0, 2, 0), 0, false, nopos);
	assert_false(hits(c, v3(0, 5, 0), v3(0, -1, 0), 0, INFINITY));
	assert_false(hits(c, v3(0, 1, -5), v3(0, 0, 1), 0, INFINITY));
	assert_false(object_inside(c, v3(0, 1, 0)));
	object_free(c);
	c = cone_new(v3(0, 1, 0), 1, v3(0, 1, 0), 0.5, false, nopos);
	assert_false(hits(c, v3(0, 5, 0), v3(0, -1, 0), -INFINITY, INFINITY));
	assert_false(object_inside(c, v3(0, 1, 0)));
	assert_true(aabb_is_finite(object_world_bounds(c)));
	object_free(c);
}

/* ---- disc ---- */

static void test_disc(void **state)
{
	(void)state;
	/* Centre <0,1,0>, normal <0,2,0> (normalised), radius 2, hole 1. */
	struct object *d = disc_new(v3(0, 1, 0), v3(0, 2, 0), 2, 1, nopos);
	vec3 dy = v3(0, -1, 0);
	struct hit h = must_hit(d, v3(1.5, 5, 0), dy, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(d, v3(1.5, 5, 0), dy, &h), 0, 1, 0, 0);
	/* From below the normal is the disc's own. */
	h = must_hit(d, v3(0, -1, -1.5), v3(0, 1, 0), 0);
	assert_near(h.t, 2, 0);
	assert_vec_near(hit_normal(d, v3(0, -1, -1.5), v3(0, 1, 0), &h), 0, 1, 0, 0);
	/* The hole, outside, both edges (included). */
	assert_false(hits(d, v3(0.5, 5, 0), dy, 0, INFINITY));
	assert_false(hits(d, v3(0, 5, 0), dy, 0, INFINITY));
	assert_false(hits(d, v3(2.0001, 5, 0), dy, 0, INFINITY));
	assert_true(hits(d, v3(2, 5, 0), dy, 0, INFINITY));
	assert_true(hits(d, v3(0, 5, -1), dy, 0, INFINITY));
	assert_false(hits(d, v3(0, 5, -0.9999), dy, 0, INFINITY));
	/* Oblique: from <-3,4,0> along <1,-1,0>: y = 1 at t = 3, x = 0 (hole). */
	assert_false(hits(d, v3(-3, 4, 0), v3(1, -1, 0), 0, INFINITY));
	assert_false(hits(d, v3(-3, 4, 0), v3(2.5, -1, 0), 0, INFINITY)); /* x = 4.5: outside */
	object_free(d);
	d = disc_new(v3(0, 1, 0), v3(0, 1, 0), 5, 1, nopos);
	h = must_hit(d, v3(-3, 4, 0), v3(2.5, -1, 0), 0);
	assert_near(h.t, 3, 0);
	/* Parallel, in the plane, away, tmax, starting on it. */
	assert_false(hits(d, v3(0, 2, 0), v3(1, 0, 0), 0, INFINITY));
	assert_false(hits(d, v3(-3, 1, 0), v3(1, 0, 0), 0, INFINITY));
	assert_false(hits(d, v3(1.5, 5, 0), v3(0, 1, 0), 0, INFINITY));
	assert_false(hits(d, v3(1.5, 5, 0), dy, 0, 4));
	assert_false(hits(d, v3(1.5, 1, 0), dy, 0, INFINITY));
	/* Inside is the plane's (POV-Ray: not limited by the radius). */
	assert_true(object_inside(d, v3(0, 0.9, 0)));
	assert_true(object_inside(d, v3(50, 0, -50)));
	assert_false(object_inside(d, v3(0, 1, 0)));
	assert_false(object_inside(d, v3(0, 1.1, 3)));
	struct hit out[2];
	assert_int_equal(all(d, v3(1.5, 5, 0), dy, 0, INFINITY, out, 2), 1);
	assert_near(out[0].t, 4, 0);
	assert_int_equal(all(d, v3(1.5, 5, 0), dy, 0, INFINITY, out, 0), 0);
	/* POV-Ray's box is 0.001 thicker each way across the disc. */
	struct aabb b = object_world_bounds(d);
	assert_vec_near(b.lo, -5, 0.999, -5, 1e-15);
	assert_vec_near(b.hi, 5, 1.001, 5, 1e-15);
	object_free(d);
}

static void test_disc_tilted_and_degenerate(void **state)
{
	(void)state;
	/* Normal <1,1,0>, centre at the origin, radius 2. */
	struct object *d = disc_new(v3(0, 0, 0), v3(1, 1, 0), 2, 0, nopos);
	struct hit h = must_hit(d, v3(3, 3, 0), v3(-1, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(d, v3(3, 3, 0), v3(-1, -1, 0), &h), sqrt(0.5), sqrt(0.5), 0, 1e-15);
	/* Along x from <-5,1,0>: the plane x + y = 0 at x = -1, distance sqrt 2. */
	h = must_hit(d, v3(-5, 1, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4, 1e-15);
	/* At distance sqrt(1.5^2 + 1.5^2 + 1.5^2) > 2 from the centre: a miss. */
	assert_false(hits(d, v3(-5, 1.5, 1.5), v3(1, 0, 0), 0, INFINITY));
	/* POV-Ray's box: [-2,2]^2 x [-0.001,0.001] in the frame taking z to
	 * minus the normal, whose x' and y' are (1/2, -1/2, -1/sqrt 2) and
	 * (-1/2, 1/2, -1/sqrt 2): looser than the ring's own box. */
	struct aabb b = object_world_bounds(d);
	double e = 2 + 0.001 * sqrt(0.5);
	assert_vec_near(b.lo, -e, -e, -2 * sqrt(2), 1e-15);
	assert_vec_near(b.hi, e, e, 2 * sqrt(2), 1e-15);
	assert_true(object_inside(d, v3(-1, 0, 7)));
	object_free(d);
	/* Transformed: scaled <1,1,3> and moved; the rim stretches in z. */
	d = disc_new(v3(0, 0, 0), v3(0, 1, 0), 1, 0, nopos);
	transform(d, xform_scale(v3(1, 1, 3)));
	transform(d, xform_translate(v3(0, 2, 0)));
	h = must_hit(d, v3(0, 5, 2.9), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(d, v3(0, 5, 2.9), v3(0, -1, 0), &h), 0, 1, 0, 0);
	assert_false(hits(d, v3(0, 5, 3.1), v3(0, -1, 0), 0, INFINITY));
	b = object_world_bounds(d);
	assert_vec_near(b.lo, -1, 1.999, -3, 1e-15);
	assert_vec_near(b.hi, 1, 2.001, 3, 1e-15);
	assert_true(object_inside(d, v3(0, 1.9, 0)));
	object_free(d);
	/* Hole as large as the disc, zero radius: nothing to hit. */
	d = disc_new(v3(0, 0, 0), v3(0, 1, 0), 1, 1, nopos);
	assert_false(hits(d, v3(1, 1, 0), v3(0, -1, 0), 0, INFINITY));
	assert_false(hits(d, v3(0.5, 1, 0), v3(0, -1, 0), 0, INFINITY));
	object_free(d);
	d = disc_new(v3(0, 0, 0), v3(0, 1, 0), 0, 0, nopos);
	assert_false(hits(d, v3(0, 1, 0), v3(0, -1, 0), 0, INFINITY));
	assert_true(object_inside(d, v3(0, -1, 0)));
	object_free(d);
	/* A zero normal becomes +y; a negative radius is its size. */
	d = disc_new(v3(0, 0, 0), v3(0, 0, 0), -1, 0, nopos);
	h = must_hit(d, v3(0.5, 1, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 1, 0);
	assert_vec_near(hit_normal(d, v3(0.5, 1, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	object_free(d);
}

/* ---- quadric ---- */

static struct object *quadric(double a, double b, double c, double d, double e, double f, double g, double h,
                              double i, double j)
{
	return quadric_new(v3(a, b, c), v3(d, e, f), v3(g, h, i), j, nopos);
}

static void test_quadric_sphere(void **state)
{
	(void)state;
	struct object *q = quadric(1, 1, 1, 0, 0, 0, 0, 0, 0, -1);
	vec3 org = v3(0, 0, -5), dz = v3(0, 0, 1);
	struct hit h = must_hit(q, org, dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(q, org, dz, &h), 0, 0, -1, 0);
	h = must_hit(q, org, dz, 4);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(q, org, dz, &h), 0, 0, 1, 0);
	assert_false(hits(q, v3(0, 1.0000001, -5), dz, 0, INFINITY));
	assert_false(hits(q, org, v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(q, org, v3(0, 0, 0), 0, INFINITY));
	/* Tangent, and just inside the tangent: the discriminant is
	 * (1 - d^2) = 2e-8 - 1e-16, held to full precision. */
	h = must_hit(q, v3(0, 1, -5), dz, 0);
	assert_near(h.t, 5, 0);
	double d = 1 - 1e-8, half = sqrt((1 - d) * (1 + d));
	h = must_hit(q, v3(0, d, -5), dz, 0);
	assert_near(h.t, 5 - half, 1e-13);
	h = must_hit(q, v3(0, d, -5), dz, 5);
	assert_near(h.t, 5 + half, 1e-13);
	/* From inside; from on the surface. */
	h = must_hit(q, v3(0, 0, 0), v3(0, 2, 0), 0);
	assert_near(h.t, 0.5, 0);
	assert_vec_near(hit_normal(q, v3(0, 0, 0), v3(0, 2, 0), &h), 0, 1, 0, 0);
	h = must_hit(q, v3(0, 0, -1), dz, 0);
	assert_near(h.t, 2, 0);
	assert_false(hits(q, v3(0, 0, -1), v3(0, 0, -1), 0, INFINITY));
	/* Inside: f <= 0 (POV-Ray 3.7 counts the surface as inside). */
	assert_true(object_inside(q, v3(0, 0, 0)));
	assert_true(object_inside(q, v3(1, 0, 0)));
	assert_false(object_inside(q, v3(1.000001, 0, 0)));
	assert_false(object_inside(q, v3(0.6, 0.6, 0.6)));
	/* all_hits. */
	struct hit out[3];
	assert_int_equal(all(q, org, dz, 0, INFINITY, out, 3), 2);
	assert_near(out[0].t, 4, 0);
	assert_near(out[1].t, 6, 0);
	assert_int_equal(all(q, org, dz, 5, INFINITY, out, 3), 1);
	assert_near(out[0].t, 6, 0);
	assert_int_equal(all(q, org, dz, 0, INFINITY, out, 1), 1);
	/* An ellipsoid's bounds are exact (to the margin). */
	struct aabb b = object_world_bounds(q);
	assert_vec_near(b.lo, -1, -1, -1, 1e-8);
	assert_vec_near(b.hi, 1, 1, 1, 1e-8);
	assert_true(b.hi.x >= 1 && b.lo.x <= -1);
	object_free(q);
	/* Far away: the unit sphere around z = 1e5 as a quadric, J = 1e10 - 1. */
	q = quadric(1, 1, 1, 0, 0, 0, 0, 0, -2e5, 1e10 - 1);
	h = must_hit(q, v3(0, 0, 0), dz, 0);
	assert_near(h.t, 1e5 - 1, 1e-9);
	h = must_hit(q, v3(0, 0, 0), dz, 1e5);
	assert_near(h.t, 1e5 + 1, 1e-9);
	/* Here f(m) = -1 is the difference of terms near 1e10, so the box
	 * keeps a margin of ~1e-5. */
	b = object_world_bounds(q);
	assert_vec_near(b.lo, -1, -1, 1e5 - 1, 1e-4);
	assert_vec_near(b.hi, 1, 1, 1e5 + 1, 1e-4);
	assert_true(b.lo.z <= 1e5 - 1 && b.hi.z >= 1e5 + 1);
	object_free(q);
}

static void test_quadric_bounds(void **state)
{
	(void)state;
	/* (x-1)^2/4 + (y+2)^2 + z^2/9 = 1. */
	struct object *q = quadric(0.25, 1, 1.0 / 9, 0, 0, 0, -0.5, 4, 0, 3.25);
	struct aabb b = object_world_bounds(q);
	assert_vec_near(b.lo, -1, -3, -3, 1e-8);
	assert_vec_near(b.hi, 3, -1, 3, 1e-8);
	assert_true(object_inside(q, v3(1, -2, 0)));
	assert_true(object_inside(q, v3(2.9, -2, 0)));
	assert_false(object_inside(q, v3(3.1, -2, 0)));
	struct hit h = must_hit(q, v3(1, -2, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 2, 1e-15);
	/* x^2 + xy + y^2 + z^2 = 3: a tilted ellipsoid reaching x = +-2 (at
	 * y = -x/2) and z = +-sqrt 3. */
	object_free(q);
	q = quadric(1, 1, 1, 1, 0, 0, 0, 0, 0, -3);
	b = object_world_bounds(q);
	assert_vec_near(b.lo, -2, -2, -sqrt(3), 1e-8);
	assert_vec_near(b.hi, 2, 2, sqrt(3), 1e-8);
	/* Its normal at <2,-1,0> is (2x + y, x + 2y, 2z) = (3, 0, 0). */
	h = must_hit(q, v3(5, -1, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, 3, 1e-15);
	assert_vec_near(hit_normal(q, v3(5, -1, 0), v3(-1, 0, 0), &h), 1, 0, 0, 1e-15);
	object_free(q);
	/* Empty (x^2 + y^2 + z^2 + 1 > 0): never hit, nothing inside, a point box. */
	q = quadric(1, 1, 1, 0, 0, 0, 0, 0, 0, 1);
	assert_false(hits(q, v3(0, 0, -5), v3(0, 0, 1), -INFINITY, INFINITY));
	assert_false(object_inside(q, v3(0, 0, 0)));
	b = object_world_bounds(q);
	assert_true(aabb_is_finite(b));
	object_free(q);
	/* Unbounded: negative definite (the outside of a sphere), a cylinder,
	 * a cone, a paraboloid, a hyperboloid, a plane. */
	static const double unb[6][10] = {
		{-1, -1, -1, 0, 0, 0, 0, 0, 0, 1}, {1, 1, 0, 0, 0, 0, 0, 0, 0, -1}, {1, 1, -1, 0, 0, 0, 0, 0, 0, 0},
		{1, 0, 1, 0, 0, 0, 0, -1, 0, 0},   {1, -1, 1, 0, 0, 0, 0, 0, 0, -1}, {0, 0, 0, 0, 0, 0, 0, 1, 0, -2},
	};
	for (int i = 0; i < 6; i++) {
		const double *c = unb[i];
		q = quadric(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9]);
		b = object_world_bounds(q);
		assert_true(b.lo.x == -INFINITY && b.lo.y == -INFINITY && b.lo.z == -INFINITY);
		assert_true(b.hi.x == INFINITY && b.hi.y == INFINITY && b.hi.z == INFINITY);
		object_free(q);
	}
	/* A thin cylinder's rounded coefficients are still unbounded: a
	 * rotated x^2 + y^2 = 1 with inexact entries. */
	double c30 = cos(M_PI / 6), s30 = sin(M_PI / 6);
	/* x' = c x - s z, y' = y: (c x - s z)^2 + y^2 - 1. */
	q = quadric(c30 * c30, 1, s30 * s30, 0, -2 * c30 * s30, 0, 0, 0, 0, -1);
	b = object_world_bounds(q);
	assert_false(aabb_is_finite(b));
	object_free(q);
}

static void test_quadric_shapes(void **state)
{
	(void)state;
	/* The infinite cylinder x^2 + y^2 = 1 along z. */
	struct object *q = quadric(1, 1, 0, 0, 0, 0, 0, 0, 0, -1);
	struct hit h = must_hit(q, v3(0, 0, 7), v3(1, 0, 0), 0);
	assert_near(h.t, 1, 0);
	assert_vec_near(hit_normal(q, v3(0, 0, 7), v3(1, 0, 0), &h), 1, 0, 0, 0);
	/* Along the axis: f is constant, no crossing. */
	assert_false(hits(q, v3(0.5, 0, -7), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(q, v3(1, 0, -7), v3(0, 0, 1), 0, INFINITY));
	object_free(q);
	/* The cone x^2 + y^2 = z^2: the ray x = 1 along z meets z = -1 and 1. */
	q = quadric(1, 1, -1, 0, 0, 0, 0, 0, 0, 0);
	h = must_hit(q, v3(1, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	vec3 ex = v3_norm(v3(1, 0, 1));
	assert_vec_near(hit_normal(q, v3(1, 0, -5), v3(0, 0, 1), &h), ex.x, ex.y, ex.z, 1e-15);
	h = must_hit(q, v3(1, 0, -5), v3(0, 0, 1), 4);
	assert_near(h.t, 6, 0);
	/* Through the apex: a finite, unit normal there. */
	h = must_hit(q, v3(-5, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 5, 0);
	vec3 n = hit_normal(q, v3(-5, 0, 0), v3(1, 0, 0), &h);
	assert_true(isfinite(n.x) && isfinite(n.y) && isfinite(n.z));
	/* Parallel to a generator, f is linear along the ray: from <0,0.5,-1>
	 * along <1,0,1>, t^2 + 0.25 - (t - 1)^2 = 2t - 0.75 vanishes at t = 0.375
	 * only. Along the generator through <0,0.5,0> f is 0.25 throughout. */
	struct hit out[3];
	assert_int_equal(all(q, v3(0, 0.5, -1), v3(1, 0, 1), -INFINITY, INFINITY, out, 3), 1);
	assert_near(out[0].t, 0.375, 0);
	assert_false(hits(q, v3(0, 0.5, -1), v3(1, 0, 1), 0.375, INFINITY));
	assert_false(hits(q, v3(0, 0.5, 0), v3(1, 0, 1), -INFINITY, INFINITY));
	object_free(q);
	/* The paraboloid y = x^2 + z^2 (f = x^2 + z^2 - y): straight down the
	 * axis the equation is linear. */
	q = quadric(1, 0, 1, 0, 0, 0, 0, -1, 0, 0);
	h = must_hit(q, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 5, 0);
	assert_vec_near(hit_normal(q, v3(0, 5, 0), v3(0, -1, 0), &h), 0, -1, 0, 0);
	assert_true(object_inside(q, v3(0, 1, 0)));
	assert_false(object_inside(q, v3(2, 1, 0)));
	h = must_hit(q, v3(-5, 1, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4, 0);
	object_free(q);
	/* Outside of the unit sphere: same crossings, the normal points into
	 * the ball (outward from the solid). */
	q = quadric(-1, -1, -1, 0, 0, 0, 0, 0, 0, 1);
	h = must_hit(q, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(q, v3(0, 0, -5), v3(0, 0, 1), &h), 0, 0, 1, 0);
	assert_true(object_inside(q, v3(0, 0, 3)));
	assert_false(object_inside(q, v3(0, 0, 0)));
	object_free(q);
	/* A plane as a quadric: y = 2. */
	q = quadric(0, 0, 0, 0, 0, 0, 0, 1, 0, -2);
	h = must_hit(q, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_false(hits(q, v3(0, 5, 0), v3(1, 0, 0), 0, INFINITY));
	object_free(q);
}

static void test_quadric_transformed(void **state)
{
	(void)state;
	/* The unit sphere scaled <2,1,1> and moved to x = 10. */
	struct object *q = quadric(1, 1, 1, 0, 0, 0, 0, 0, 0, -1);
	transform(q, xform_scale(v3(2, 1, 1)));
	transform(q, xform_translate(v3(10, 0, 0)));
	struct hit h = must_hit(q, v3(0, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 8, 0);
	assert_vec_near(hit_normal(q, v3(0, 0, 0), v3(1, 0, 0), &h), -1, 0, 0, 0);
	h = must_hit(q, v3(10, 0.5, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, sqrt(3), 1e-15);
	struct aabb b = object_world_bounds(q);
	assert_vec_near(b.lo, 8, -1, -1, 1e-8);
	assert_vec_near(b.hi, 12, 1, 1, 1e-8);
	assert_true(object_inside(q, v3(11.9, 0, 0)));
	object_free(q);
}

/* ---- superellipsoid ---- */

/* F of superellipsoid { <e, n> }, evaluated independently of the primitive. */
static double se_f(double e, double n, vec3 p)
{
	return pow(pow(fabs(p.x), 2 / e) + pow(fabs(p.y), 2 / e), e / n) + pow(fabs(p.z), 2 / n) - 1;
}

/* A root of g(x) = se_f(on the line) in [lo, hi] where the sign differs,
 * by plain bisection to the last bit. */
static double bisect_line(double e, double n, vec3 o, vec3 d, double lo, double hi)
{
	double flo = se_f(e, n, v3_madd(o, d, lo));
	for (int i = 0; i < 200; i++) {
		double m = 0.5 * (lo + hi);
		if (m == lo || m == hi)
			break;
		double fm = se_f(e, n, v3_madd(o, d, m));
		if ((fm < 0) == (flo < 0))
			lo = m;
		else
			hi = m;
	}
	return 0.5 * (lo + hi);
}

static void test_se_sphere(void **state)
{
	(void)state;
	/* e = n = 1 is the unit sphere: compare with the sphere primitive. */
	struct object *s = superellipsoid_new(1, 1, nopos);
	struct object *ref = sphere_new(v3(0, 0, 0), 1, nopos);
	assert_string_equal(s->ops->name, "superellipsoid");
	uint32_t seed = 12345;
	int nhit = 0;
	for (int i = 0; i < 2000; i++) {
		double u[6];
		for (int k = 0; k < 6; k++) {
			seed = seed * 1664525u + 1013904223u;
			u[k] = (seed >> 8) / 16777216.0 * 2 - 1;
		}
		vec3 org = v3(3 * u[0], 3 * u[1], 3 * u[2]);
		vec3 dir = v3_sub(v3(0.8 * u[3], 0.8 * u[4], 0.8 * u[5]), org);
		struct ray r = mkray(org, dir);
		struct hit a[4], b[4];
		int na = s->ops->all_hits(s, &r, 0, INFINITY, a, 4);
		int nb = ref->ops->all_hits(ref, &r, 0, INFINITY, b, 4);
		assert_int_equal(na, nb);
		for (int k = 0; k < na; k++) {
			assert_near(a[k].t, b[k].t, 1e-13 * (1 + b[k].t));
			vec3 p = v3_madd(org, dir, a[k].t);
			vec3 n = object_normal(s, p, &a[k]), m = v3_norm(p);
			assert_vec_near(n, m.x, m.y, m.z, 1e-12);
		}
		nhit += na;
	}
	assert_true(nhit > 1000);
	object_free(ref);
	/* Axis-aligned: exact. */
	struct hit h = must_hit(s, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(s, v3(0, 0, -5), v3(0, 0, 1), &h), 0, 0, -1, 0);
	object_free(s);
}

static void test_se_boxlike(void **state)
{
	(void)state;
	/* e = n = 0.1: a box with edges rounded over ~0.03. */
	const double e = 0.1, n = 0.1, p = 20;
	struct object *s = superellipsoid_new(e, n, nopos);
	vec3 dz = v3(0, 0, 1);
	struct hit h = must_hit(s, v3(0, 0, -5), dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(s, v3(0, 0, -5), dz, &h), 0, 0, -1, 0);
	h = must_hit(s, v3(0, 0, -5), dz, 4);
	assert_near(h.t, 6, 0);
	/* Near the face: (x^20 + y^20) + z^20 = 1 at x = y = 0.5. */
	double zf = pow(1 - 2 * pow(0.5, p), 1 / p);
	h = must_hit(s, v3(0.5, 0.5, -5), dz, 0);
	assert_near(h.t, 5 - zf, 1e-14);
	assert_vec_near(hit_normal(s, v3(0.5, 0.5, -5), dz, &h), 0, 0, -1, 1e-5);
	/* In the plane z = 0 at y = c near the edge: x = (1 - c^20)^(1/20). */
	for (double c = 0.9; c < 1; c += 0.0123) {
		double x = pow(1 - pow(c, p), 1 / p);
		h = must_hit(s, v3(-5, c, 0), v3(1, 0, 0), 0);
		assert_near(h.t, 5 - x, 1e-13);
		h = must_hit(s, v3(-5, c, 0), v3(1, 0, 0), 5);
		assert_near(h.t, 5 + x, 1e-13);
		vec3 nn = hit_normal(s, v3(-5, c, 0), v3(1, 0, 0), &h);
		vec3 ex = v3_norm(v3(pow(x, p - 1), pow(c, p - 1), 0));
		assert_vec_near(nn, ex.x, ex.y, ex.z, 1e-12);
	}
	/* Just outside the box face, and outside the rounded corner in the
	 * plane z = 0 at the diagonal: missed. */
	assert_false(hits(s, v3(-5, 1.0000001, 0), v3(1, 0, 0), 0, INFINITY));
	assert_false(hits(s, v3(-5, 0.99, 0.99), v3(1, 0, 0), 0, INFINITY));
	/* Thin features: lines x + y = s just inside the rounded vertical edge,
	 * whose tip along the diagonal is at x = y = 2^(-1/20), s* = 2^(1 - 1/20).
	 * The two crossings come within 1e-4 (then 2e-6) of each other and must
	 * both be found. */
	double sstar = 2 * pow(2, -1 / p);
	for (int k = 0; k < 2; k++) {
		double sl = sstar * (1 - (k ? 1e-12 : 1e-9));
		vec3 o = v3(sl / 2 - 5, sl / 2 + 5, 0), d = v3(1, -1, 0);
		/* The midpoint of the chord is at t = 5, inside. */
		assert_true(se_f(e, n, v3_madd(o, d, 5)) < 0);
		double t0 = bisect_line(e, n, o, d, 0, 5), t1 = bisect_line(e, n, o, d, 5, 10);
		assert_true(t1 - t0 < 1e-3 && t1 - t0 > 0);
		struct hit out[4];
		int cnt = all(s, o, d, 0, INFINITY, out, 4);
		assert_int_equal(cnt, 2);
		/* Roots this close to a tangency are ill-conditioned: F's last
		 * bit moves them by ~1e-12. */
		assert_near(out[0].t, t0, 1e-10);
		assert_near(out[1].t, t1, 1e-10);
	}
	/* A corner of the box-like shape: the tip along <1,1,1> at
	 * 3 x^20 = 1; a line across the diagonal just inside it. */
	double xc = pow(3, -1 / p) * (1 - 1e-10);
	vec3 o = v3(xc + 5, xc - 5, xc), d = v3(-1, 1, 0);
	struct hit out[4];
	int cnt = all(s, o, d, 0, INFINITY, out, 4);
	assert_int_equal(cnt, 2);
	assert_near(out[0].t + out[1].t, 10, 1e-9);
	assert_true(out[1].t - out[0].t > 0 && out[1].t - out[0].t < 1e-3);
	/* Inside. */
	assert_true(object_inside(s, v3(0.9, 0.9, 0.9)));
	assert_true(object_inside(s, v3(0, 0, 0.99)));
	assert_false(object_inside(s, v3(0.99, 0.99, 0.99)));
	assert_false(object_inside(s, v3(0, 0, 1.01)));
	object_free(s);
}

static void test_se_stars_and_flats(void **state)
{
	(void)state;
	/* e = n = 3: a concave star; in z = 0 the astroid x^(2/3) + y^(2/3) = 1.
	 * The line x + y = 0.9 crosses it four times. */
	struct object *s = superellipsoid_new(3, 3, nopos);
	vec3 o = v3(2.9, -2, 0), d = v3(-1, 1, 0); /* x = 2.9 - t, y = t - 2 */
	double br[5] = {1.8, 2.0, 2.45, 2.9, 3.0}; /* y = -0.2, 0, 0.45, 0.9, 1 */
	double ex[4];
	ex[0] = bisect_line(3, 3, o, d, br[0], br[1]);
	ex[1] = bisect_line(3, 3, o, d, br[1], br[2]);
	ex[2] = bisect_line(3, 3, o, d, br[2], br[3]);
	ex[3] = bisect_line(3, 3, o, d, br[3], br[4]);
	struct hit out[8];
	int cnt = all(s, o, d, 0, INFINITY, out, 8);
	assert_int_equal(cnt, 4);
	for (int i = 0; i < 4; i++)
		assert_near(out[i].t, ex[i], 1e-13);
	/* Through the centre along the axes: the spikes' tips at distance 1. */
	struct hit h = must_hit(s, v3(-5, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4, 1e-14);
	vec3 nn = hit_normal(s, v3(-5, 0, 0), v3(1, 0, 0), &h);
	assert_true(isfinite(nn.x) && isfinite(nn.y) && isfinite(nn.z));
	h = must_hit(s, v3(0, 0, 5), v3(0, 0, -1), 0);
	assert_near(h.t, 4, 1e-14);
	assert_true(object_inside(s, v3(0.3, 0.3, 0)));
	assert_true(object_inside(s, v3(0.1, 0.1, 0)));
	assert_false(object_inside(s, v3(0.4, 0.4, 0)));
	object_free(s);

	/* e = n = 2: the octahedron |x| + |y| + |z| = 1. */
	s = superellipsoid_new(2, 2, nopos);
	h = must_hit(s, v3(0.2, 0.3, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4.5, 1e-14);
	vec3 n1 = hit_normal(s, v3(0.2, 0.3, -5), v3(0, 0, 1), &h);
	assert_vec_near(n1, 1 / sqrt(3), 1 / sqrt(3), -1 / sqrt(3), 1e-14);
	h = must_hit(s, v3(0.2, 0.3, -5), v3(0, 0, 1), 4.5);
	assert_near(h.t, 5.5, 1e-14);
	/* A ray lying in a face: it ends, whatever it reports, with finite
	 * hits in range. */
	cnt = all(s, v3(0.5, 0.5, 0), v3(1, -1, 0), -INFINITY, INFINITY, out, 8);
	assert_true(cnt >= 0 && cnt <= 8);
	cnt = all(s, v3(1.0 / 3, 1.0 / 3, 1.0 / 3), v3(1, 0, -1), -INFINITY, INFINITY, out, 8);
	assert_true(cnt >= 0 && cnt <= 8);
	object_free(s);

	/* Mixed: e = 0.5, n = 3, and e = 4, n = 0.3; along the axes the tips are
	 * at 1, and in z = c the section is (x^4 + y^4)^(1/6) = 1 - c^(2/3). */
	s = superellipsoid_new(0.5, 3, nopos);
	h = must_hit(s, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 1e-14);
	double c = 0.2, x = pow(pow(1 - pow(c, 2.0 / 3), 6), 0.25);
	h = must_hit(s, v3(-5, 0, c), v3(1, 0, 0), 0);
	assert_near(h.t, 5 - x, 1e-13);
	object_free(s);
	s = superellipsoid_new(4, 0.3, nopos);
	h = must_hit(s, v3(-5, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4, 1e-14);
	h = must_hit(s, v3(0, 0, 5), v3(0, 0, -1), 0);
	assert_near(h.t, 4, 1e-14);
	object_free(s);
}

static void test_se_inside_surface_bounds(void **state)
{
	(void)state;
	struct object *s = superellipsoid_new(0.5, 0.5, nopos);
	/* From the centre, out through the face points that are exact. */
	struct hit h = must_hit(s, v3(0, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 1, 1e-15);
	assert_vec_near(hit_normal(s, v3(0, 0, 0), v3(1, 0, 0), &h), 1, 0, 0, 1e-15);
	h = must_hit(s, v3(0, 0, 0), v3(0, -0.5, 0), 0);
	assert_near(h.t, 2, 1e-15);
	/* Starting exactly on the surface: t = 0 is excluded. */
	h = must_hit(s, v3(0, 0, -1), v3(0, 0, 1), 0);
	assert_near(h.t, 2, 1e-15);
	assert_false(hits(s, v3(0, 0, -1), v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(s, v3(1, 0, 0), v3(1, 0, 0), 0, INFINITY));
	/* tmax and the ray ending on the surface. */
	assert_false(hits(s, v3(0, 0, -5), v3(0, 0, 1), 0, 4));
	assert_true(hits(s, v3(0, 0, -5), v3(0, 0, 1), 0, 4.000001));
	/* Inside as POV-Ray 3.7 answers it (F <= 0; the surface counts). */
	assert_true(object_inside(s, v3(0, 0, 0)));
	assert_true(object_inside(s, v3(1, 0, 0)));
	assert_false(object_inside(s, v3(1 + 1e-9, 0, 0)));
	assert_false(object_inside(s, v3(0.9, 0.9, 0.9)));
	assert_true(object_inside(s, v3(0.7, 0.7, 0)));
	/* POV-Ray's box: the cube widened by 1e-4. */
	struct aabb b = object_world_bounds(s);
	assert_vec_near(b.lo, -1.0001, -1.0001, -1.0001, 0);
	assert_vec_near(b.hi, 1.0001, 1.0001, 1.0001, 0);
	/* all_hits honours max and the range. */
	struct hit out[4];
	assert_int_equal(all(s, v3(0, 0.3, -5), v3(0, 0, 1), 0, INFINITY, out, 4), 2);
	assert_int_equal(all(s, v3(0, 0.3, -5), v3(0, 0, 1), 0, INFINITY, out, 1), 1);
	assert_int_equal(all(s, v3(0, 0.3, -5), v3(0, 0, 1), 5, INFINITY, out, 4), 1);
	assert_int_equal(all(s, v3(0, 0.3, -5), v3(0, 0, 1), 0, INFINITY, out, 0), 0);
	assert_int_equal(all(s, v3(0, 0, 0), v3(0, 0, 0), -INFINITY, INFINITY, out, 4), 0);
	object_free(s);
	/* Transformed: scale 2, move to y = 10. */
	s = superellipsoid_new(0.5, 0.5, nopos);
	transform(s, xform_scale(v3(2, 2, 2)));
	transform(s, xform_translate(v3(0, 10, 0)));
	h = must_hit(s, v3(-5, 10, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 3, 1e-14);
	assert_vec_near(hit_normal(s, v3(-5, 10, 0), v3(1, 0, 0), &h), -1, 0, 0, 1e-14);
	b = object_world_bounds(s);
	assert_vec_near(b.lo, -2.0002, 7.9998, -2.0002, 1e-14);
	assert_vec_near(b.hi, 2.0002, 12.0002, 2.0002, 1e-14);
	assert_true(object_inside(s, v3(1.9, 10, 0)));
	object_free(s);
	/* Out-of-range exponents are raised to the minimum: a finite shape. */
	s = superellipsoid_new(0, -1, nopos);
	h = must_hit(s, v3(0.3, 0.2, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 1e-9);
	object_free(s);
}

/* Normals stay finite and unit at extreme exponents and at singular
 * points (cusps, axes, edges). */
static void test_se_normals_extreme(void **state)
{
	(void)state;
	static const double en[][2] = {{0.001, 0.001}, {0.001, 1}, {5, 5}, {0.05, 4}, {4, 0.05}, {2, 2}, {1, 1}};
	static const double pts[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.01, 0.01, 0.9999}, {1e-200, 0.5, 0.5},
	                                {0.999, 0.999, 0}, {0.3, 0.3, 0.3}, {0, 0, 0}, {-0.2, 0.7, -0.1}};
	for (size_t i = 0; i < sizeof en / sizeof en[0]; i++) {
		struct object *s = superellipsoid_new(en[i][0], en[i][1], nopos);
		for (size_t k = 0; k < sizeof pts / sizeof pts[0]; k++) {
			vec3 n = object_normal(s, v3(pts[k][0], pts[k][1], pts[k][2]), NULL);
			if (!(isfinite(n.x) && isfinite(n.y) && isfinite(n.z)))
				fail_msg("e %g n %g at point %zu: normal <%g,%g,%g>", en[i][0], en[i][1], k, n.x, n.y,
				         n.z);
			assert_near(v3_len(n), 1, 1e-14);
		}
		object_free(s);
	}
}

/* Every sign change of F seen by dense sampling along random rays is
 * matched by a reported crossing, each crossing really is one, and the
 * crossings alternate between outside and inside. */
static void test_se_against_sampling(void **state)
{
	(void)state;
	static const double en[][2] = {{0.1, 0.1}, {0.3, 2.5}, {3, 3}, {1, 0.2}, {2, 2}, {0.5, 3},
	                               {4, 0.3}, {0.05, 0.05}, {2.5, 1}, {1.5, 1.5}};
	enum { RAYS = 150, SAMPLES = 4000 };
	uint32_t seed = 777;
	for (size_t k = 0; k < sizeof en / sizeof en[0]; k++) {
		double e = en[k][0], n = en[k][1];
		struct object *s = superellipsoid_new(e, n, nopos);
		int total = 0;
		for (int i = 0; i < RAYS; i++) {
			double u[6];
			for (int j = 0; j < 6; j++) {
				seed = seed * 1664525u + 1013904223u;
				u[j] = (seed >> 8) / 16777216.0 * 2 - 1;
			}
			vec3 org = v3_scale(v3_norm(v3(u[0], u[1], u[2] + 0.01)), 4);
			vec3 dir = v3_sub(v3(u[3], u[4], u[5]), org); /* aimed into the box */
			struct ray r = mkray(org, dir);
			struct hit out[16];
			int cnt = s->ops->all_hits(s, &r, 0, INFINITY, out, 16);
			total += cnt;
			/* |org| = 4 and |dir| >= 4 - sqrt 3, so the box lies within
			 * t < (4 + sqrt 3) / (4 - sqrt 3) < 3: sample [0, 3]. */
			double prev_t = 0;
			bool prev_in = se_f(e, n, org) < 0;
			int matched = 0;
			for (int j = 1; j <= SAMPLES; j++) {
				double t = 3.0 * j / SAMPLES;
				bool in = se_f(e, n, v3_madd(org, dir, t)) < 0;
				if (in != prev_in) {
					bool found = false;
					for (int m = 0; m < cnt; m++)
						if (out[m].t >= prev_t - 1e-12 && out[m].t <= t + 1e-12)
							found = true;
					if (!found)
						fail_msg("e %g n %g ray %d: sign change in [%.17g, %.17g] missed", e, n, i,
						         prev_t, t);
					matched++;
				}
				prev_t = t;
				prev_in = in;
			}
			assert_true(cnt >= matched);
			for (int m = 0; m < cnt; m++) {
				double t = out[m].t;
				double dt = 1e-9 * (1 + t);
				/* The crossing: inside on one side, outside on the other,
				 * alternating (the ray starts outside). */
				bool before = se_f(e, n, v3_madd(org, dir, t - dt)) < 0;
				bool after = se_f(e, n, v3_madd(org, dir, t + dt)) < 0;
				if (before == after)
					fail_msg("e %g n %g ray %d: hit %d at t = %.17g is no crossing", e, n, i, m, t);
				assert_true(after == (m % 2 == 0));
				if (m > 0)
					assert_true(t > out[m - 1].t);
				vec3 nn = object_normal(s, v3_madd(org, dir, t), &out[m]);
				assert_near(v3_len(nn), 1, 1e-14);
				/* The normal points out: a step along it leaves the solid. */
				if (m % 2 == 0)
					assert_true(v3_dot(nn, dir) <= 1e-9 * v3_len(dir));
			}
		}
		assert_true(total > RAYS / 2);
		object_free(s);
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cylinder_hit_miss),
		cmocka_unit_test(test_cylinder_grazing),
		cmocka_unit_test(test_cylinder_inside_and_on_surface),
		cmocka_unit_test(test_cylinder_open),
		cmocka_unit_test(test_cylinder_oblique_and_transformed),
		cmocka_unit_test(test_cylinder_degenerate),
		cmocka_unit_test(test_cone_pointed),
		cmocka_unit_test(test_cone_frustum),
		cmocka_unit_test(test_cone_signed_radii),
		cmocka_unit_test(test_cone_transformed_and_degenerate),
		cmocka_unit_test(test_disc),
		cmocka_unit_test(test_disc_tilted_and_degenerate),
		cmocka_unit_test(test_quadric_sphere),
		cmocka_unit_test(test_quadric_bounds),
		cmocka_unit_test(test_quadric_shapes),
		cmocka_unit_test(test_quadric_transformed),
		cmocka_unit_test(test_se_sphere),
		cmocka_unit_test(test_se_boxlike),
		cmocka_unit_test(test_se_stars_and_flats),
		cmocka_unit_test(test_se_inside_surface_bounds),
		cmocka_unit_test(test_se_normals_extreme),
		cmocka_unit_test(test_se_against_sampling),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

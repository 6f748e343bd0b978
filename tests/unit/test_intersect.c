/* test_intersect.c: unit tests for ray intersection. Spheres, planes and
 * boxes (src/geom/shapes.h) are hit through the shape-independent layer
 * (src/scene/object.h) and compared with analytic answers: hits, misses,
 * grazing rays, rays starting inside or on the surface, transformed
 * objects, inside tests and bounds. The BVH (src/accel/bvh.h) must agree
 * exactly with brute force over the same objects. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "accel/bvh.h"
#include "geom/shapes.h"
#include "math/hash.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* ---- sphere ---- */

static void test_sphere_hit_miss(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	vec3 org = v3(0, 0, -5), dz = v3(0, 0, 1);
	struct hit h = must_hit(s, org, dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(s, org, dz, &h), 0, 0, -1, 0);
	/* Past the near crossing: the far one, with the outward normal. */
	h = must_hit(s, org, dz, 4.5);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(s, org, dz, &h), 0, 0, 1, 0);
	/* tmax cuts it off; both bounds are exclusive. */
	assert_false(hits(s, org, dz, 0, 3.9));
	assert_false(hits(s, org, dz, 0, 4));
	assert_true(hits(s, org, dz, 0, 4.0000001));
	assert_false(hits(s, org, dz, 6, INFINITY));
	/* A longer direction: t shrinks in proportion. */
	h = must_hit(s, org, v3(0, 0, 2), 0);
	assert_near(h.t, 2, 0);
	/* Misses: off to the side, pointing away, behind. */
	assert_false(hits(s, v3(0, 2, -5), dz, 0, INFINITY));
	assert_false(hits(s, v3(0, 1.0000001, -5), dz, 0, INFINITY));
	assert_false(hits(s, org, v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(s, v3(0, 0, 5), dz, 0, INFINITY));
	/* A zero direction never hits. */
	assert_false(hits(s, org, v3(0, 0, 0), 0, INFINITY));
	/* An oblique ray: from <-3,-4,0> toward the centre, t = 4 at <-0.6,-0.8,0>. */
	h = must_hit(s, v3(-3, -4, 0), v3(0.6, 0.8, 0), 0);
	assert_near(h.t, 4, 1e-15);
	assert_vec_near(hit_normal(s, v3(-3, -4, 0), v3(0.6, 0.8, 0), &h), -0.6, -0.8, 0, 1e-15);
	object_free(s);
}

static void test_sphere_grazing(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(1, 2, 3), 2, nopos);
	vec3 dz = v3(0, 0, 1);
	/* Exactly tangent at x = 3: touches at t = 5. */
	struct hit h = must_hit(s, v3(3, 2, -2), dz, 0);
	assert_near(h.t, 5, 1e-15);
	/* Just outside misses; just inside hits near the analytic roots
	 * 5 -+ sqrt(r^2 - d^2). */
	assert_false(hits(s, v3(3 + 1e-9, 2, -2), dz, 0, INFINITY));
	double d = 2 - 1e-6, half = sqrt(4 - d * d);
	h = must_hit(s, v3(1 + d, 2, -2), dz, 0);
	assert_near(h.t, 5 - half, 1e-12);
	h = must_hit(s, v3(1 + d, 2, -2), dz, 5);
	assert_near(h.t, 5 + half, 1e-12);
	/* Grazing normals are still unit and point sideways. */
	h = must_hit(s, v3(1, 2 + d, -2), dz, 0);
	vec3 n = hit_normal(s, v3(1, 2 + d, -2), dz, &h);
	assert_near(n.y, d / 2, 1e-9);
	object_free(s);
}

static void test_sphere_inside_and_on_surface(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	/* From the centre: one crossing, with the outward normal. */
	vec3 o = v3(0, 0, 0);
	struct hit h = must_hit(s, o, v3(1, 0, 0), 0);
	assert_near(h.t, 1, 0);
	assert_vec_near(hit_normal(s, o, v3(1, 0, 0), &h), 1, 0, 0, 0);
	h = must_hit(s, v3(0.5, 0, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, 1.5, 0);
	/* Starting exactly on the surface: t = 0 is excluded by tmin = 0. */
	h = must_hit(s, v3(0, 0, -1), v3(0, 0, 1), 0);
	assert_near(h.t, 2, 0);
	assert_false(hits(s, v3(0, 0, -1), v3(0, 0, -1), 0, INFINITY));
	h = must_hit(s, v3(0, 1, 0), v3(0, -0.5, 0), 0);
	assert_near(h.t, 4, 0);
	/* ...and by a small positive tmin as the renderer uses. */
	h = must_hit(s, v3(0, 0, -1), v3(0, 0, 1), 1e-6);
	assert_near(h.t, 2, 0);
	object_free(s);
}

static void test_sphere_all_hits(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	struct ray r = mkray(v3(0, 0, -5), v3(0, 0, 1));
	struct hit out[4];
	assert_int_equal(s->ops->all_hits(s, &r, 0, INFINITY, out, 4), 2);
	assert_near(out[0].t, 4, 0);
	assert_near(out[1].t, 6, 0);
	assert_ptr_equal(out[0].obj, s);
	assert_ptr_equal(out[1].obj, s);
	assert_int_not_equal(out[0].part, out[1].part);
	/* max bounds the count; the nearest comes first. */
	assert_int_equal(s->ops->all_hits(s, &r, 0, INFINITY, out, 1), 1);
	assert_near(out[0].t, 4, 0);
	/* Range limits. */
	assert_int_equal(s->ops->all_hits(s, &r, 5, INFINITY, out, 4), 1);
	assert_near(out[0].t, 6, 0);
	assert_int_equal(s->ops->all_hits(s, &r, 0, 5, out, 4), 1);
	assert_near(out[0].t, 4, 0);
	assert_int_equal(s->ops->all_hits(s, &r, 4, 6, out, 4), 0);
	/* From inside: one. Missing: none. */
	r = mkray(v3(0, 0, 0), v3(0, 1, 0));
	assert_int_equal(s->ops->all_hits(s, &r, 0, INFINITY, out, 4), 1);
	assert_near(out[0].t, 1, 0);
	r = mkray(v3(0, 3, -5), v3(0, 0, 1));
	assert_int_equal(s->ops->all_hits(s, &r, 0, INFINITY, out, 4), 0);
	object_free(s);
}

static void test_sphere_inside_bounds(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(1, 2, 3), -2, nopos); /* a negative radius is its size */
	assert_true(object_inside(s, v3(1, 2, 3)));
	assert_true(object_inside(s, v3(2.9, 2, 3)));
	assert_false(object_inside(s, v3(3.1, 2, 3)));
	assert_false(object_inside(s, v3(3, 4, 3)));
	struct aabb b = object_world_bounds(s);
	assert_vec_near(b.lo, -1, 0, 1, 0);
	assert_vec_near(b.hi, 3, 4, 5, 0);
	assert_true(aabb_is_finite(object_world_bounds(s)));
	s->flags |= OBJ_INVERSE;
	assert_false(object_inside(s, v3(1, 2, 3)));
	assert_true(object_inside(s, v3(3.1, 2, 3)));
	/* An inverted object keeps its box, as POV-Ray's min_extent reports
	 * it (its surface lies there), and prepare marks it loose: its inside
	 * reaches beyond the box, so inside tests must not cull by it. */
	b = object_world_bounds(s);
	assert_vec_near(b.lo, -1, 0, 1, 0);
	assert_vec_near(b.hi, 3, 4, 5, 0);
	assert_false(s->loose);
	object_prepare(s);
	assert_true(s->loose);
	object_free(s);
}

static void test_sphere_far_from_origin(void **state)
{
	(void)state;
	/* Centre 1e5 away. Forming b^2 - ac directly would lose about ten
	 * digits of the discriminant here. */
	struct object *s = sphere_new(v3(0, 0, 1e5), 1, nopos);
	struct hit h = must_hit(s, v3(0, 0, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 1e5 - 1, 1e-9);
	h = must_hit(s, v3(0, 0.5, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 1e5 - sqrt(0.75), 1e-9);
	h = must_hit(s, v3(0, 0.5, 0), v3(0, 0, 1), 1e5);
	assert_near(h.t, 1e5 + sqrt(0.75), 1e-9);
	vec3 n = hit_normal(s, v3(0, 0.5, 0), v3(0, 0, 1), &h);
	assert_vec_near(n, 0, 0.5, sqrt(0.75), 1e-9);
	object_free(s);
	/* Off-axis: centre <60000, 0, 80000>, ray from the origin straight at it. */
	s = sphere_new(v3(60000, 0, 80000), 1, nopos);
	vec3 dir = v3(0.6, 0, 0.8);
	h = must_hit(s, v3(0, 0, 0), dir, 0);
	assert_near(h.t * v3_len(dir), 1e5 - 1, 1e-9);
	/* Grazing at distance 0.999 from the centre, seen from 1e5 away. */
	object_free(s);
	s = sphere_new(v3(1e5, 1e5, 0), 1, nopos);
	h = must_hit(s, v3(0, 1e5 + 0.999, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 1e5 - sqrt(1 - 0.999 * 0.999), 1e-9);
	object_free(s);
}

static void test_sphere_tiny(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(0, 0, 0), 1e-4, nopos);
	struct hit h = must_hit(s, v3(0, 0, -1), v3(0, 0, 1), 0);
	assert_near(h.t, 1 - 1e-4, 1e-15);
	/* Half a radius off axis: t = 1 - 1e-4 sqrt(0.75). */
	h = must_hit(s, v3(0, 0.5e-4, -1), v3(0, 0, 1), 0);
	assert_near(h.t, 1 - 1e-4 * sqrt(0.75), 1e-15);
	vec3 n = hit_normal(s, v3(0, 0.5e-4, -1), v3(0, 0, 1), &h);
	assert_vec_near(n, 0, 0.5, -sqrt(0.75), 1e-10);
	h = must_hit(s, v3(0, 0.5e-4, -1), v3(0, 0, 1), 1);
	assert_near(h.t, 1 + 1e-4 * sqrt(0.75), 1e-15);
	assert_false(hits(s, v3(0, 1.0001e-4, -1), v3(0, 0, 1), 0, INFINITY));
	assert_true(object_inside(s, v3(0, 0.9e-4, 0)));
	assert_false(object_inside(s, v3(0, 1.1e-4, 0)));
	object_free(s);
}

/* ---- plane ---- */

static void test_plane(void **state)
{
	(void)state;
	struct object *p = plane_new(v3(0, 1, 0), 0, nopos);
	assert_false(aabb_is_finite(object_world_bounds(p)));
	struct hit h = must_hit(p, v3(1, 5, 2), v3(0, -1, 0), 0);
	assert_near(h.t, 5, 0);
	assert_vec_near(hit_normal(p, v3(1, 5, 2), v3(0, -1, 0), &h), 0, 1, 0, 0);
	/* From below, the normal is still the plane's own. */
	h = must_hit(p, v3(0, -2, 0), v3(0, 4, 0), 0);
	assert_near(h.t, 0.5, 0);
	assert_vec_near(hit_normal(p, v3(0, -2, 0), v3(0, 4, 0), &h), 0, 1, 0, 0);
	/* Oblique. */
	h = must_hit(p, v3(0, 3, 0), v3(1, -1, 1), 0);
	assert_near(h.t, 3, 0);
	/* Away, parallel above, and lying in the plane all miss. */
	assert_false(hits(p, v3(0, 5, 0), v3(0, 1, 0), 0, INFINITY));
	assert_false(hits(p, v3(0, 5, 0), v3(1, 0, 0), 0, INFINITY));
	assert_false(hits(p, v3(0, 0, 0), v3(1, 0, 1), 0, INFINITY));
	/* Starting on the plane: t = 0 is excluded either way. */
	assert_false(hits(p, v3(3, 0, 4), v3(0, 1, 0), 0, INFINITY));
	assert_false(hits(p, v3(3, 0, 4), v3(0, -1, 0), 0, INFINITY));
	/* tmax. */
	assert_false(hits(p, v3(0, 5, 0), v3(0, -1, 0), 0, 5));
	/* Inside is the side the normal points away from. */
	assert_true(object_inside(p, v3(0, -1, 0)));
	assert_false(object_inside(p, v3(0, 1, 0)));
	/* Unbounded. */
	struct aabb b = object_world_bounds(p);
	assert_true(isinf(b.lo.x) && b.lo.x < 0 && isinf(b.hi.y) && b.hi.y > 0);
	/* all_hits: one crossing. */
	struct ray r = mkray(v3(0, 1, 0), v3(0, -1, 0));
	struct hit out[2];
	assert_int_equal(p->ops->all_hits(p, &r, 0, INFINITY, out, 2), 1);
	assert_near(out[0].t, 1, 0);
	assert_ptr_equal(out[0].obj, p);
	assert_int_equal(p->ops->all_hits(p, &r, 0, INFINITY, out, 0), 0);
	object_free(p);
}

static void test_plane_normal_and_distance(void **state)
{
	(void)state;
	/* plane { <0,2,0>, 1 }: the normal is normalised, the surface is y = 1. */
	struct object *p = plane_new(v3(0, 2, 0), 1, nopos);
	struct hit h = must_hit(p, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(p, v3(0, 5, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	assert_true(object_inside(p, v3(0, 0.9, 0)));
	assert_false(object_inside(p, v3(0, 1.1, 0)));
	object_free(p);
	/* A tilted plane <1,1,0>, sqrt 2: the surface x + y = 2. */
	p = plane_new(v3(1, 1, 0), sqrt(2), nopos);
	h = must_hit(p, v3(0, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 2, 1e-15);
	assert_vec_near(hit_normal(p, v3(0, 0, 0), v3(1, 0, 0), &h), sqrt(0.5), sqrt(0.5), 0, 1e-15);
	/* Parallel to it. */
	assert_false(hits(p, v3(0, 0, 0), v3(1, -1, 0), 0, INFINITY));
	assert_true(object_inside(p, v3(0, 0, 0)));
	assert_false(object_inside(p, v3(2, 2, 0)));
	object_free(p);
	/* Negative distance: y = -3. */
	p = plane_new(v3(0, 1, 0), -3, nopos);
	h = must_hit(p, v3(0, 0, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	object_free(p);
}

/* ---- box ---- */

static void test_box_hit_miss(void **state)
{
	(void)state;
	/* Corners in either order. */
	struct object *b = box_new(v3(1, 1, 1), v3(-1, -1, -1), nopos);
	vec3 org = v3(0, 0, -5), dz = v3(0, 0, 1);
	struct hit h = must_hit(b, org, dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(b, org, dz, &h), 0, 0, -1, 0);
	h = must_hit(b, org, dz, 4);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(b, org, dz, &h), 0, 0, 1, 0);
	/* Each face from outside, with its outward normal. */
	static const double faces[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
	for (int f = 0; f < 6; f++) {
		vec3 n = v3(faces[f][0], faces[f][1], faces[f][2]);
		vec3 o = v3_madd(v3(0.25, -0.125, 0.5), n, 10); /* off-centre, 10 out */
		/* The face's own coordinate of o is 10 (+-offset), so t = 10 - 1 +- offset. */
		double off = v3_dot(v3(0.25, -0.125, 0.5), n);
		h = must_hit(b, o, v3_neg(n), 0);
		assert_near(h.t, 10 + off - 1, 1e-15);
		vec3 hn = hit_normal(b, o, v3_neg(n), &h);
		assert_vec_near(hn, n.x, n.y, n.z, 0);
	}
	/* Misses. */
	assert_false(hits(b, v3(2, 0, -5), dz, 0, INFINITY));
	assert_false(hits(b, org, v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(b, v3(0, 0, -5), v3(1, 0, 1), 0, INFINITY)); /* passes x = 1 before z = -1 */
	assert_false(hits(b, org, dz, 0, 4));
	/* Diagonal through the corners: in at t = 1, out at t = 3. */
	h = must_hit(b, v3(-2, -2, -2), v3(1, 1, 1), 0);
	assert_near(h.t, 1, 0);
	h = must_hit(b, v3(-2, -2, -2), v3(1, 1, 1), 1);
	assert_near(h.t, 3, 0);
	/* An oblique ray entering the top face. */
	h = must_hit(b, v3(-3, 4, 0), v3(1, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(b, v3(-3, 4, 0), v3(1, -1, 0), &h), 0, 1, 0, 0);
	object_free(b);
}

static void test_box_parallel(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos);
	vec3 dz = v3(0, 0, 1);
	/* Parallel to the y faces, within the slab: hits the z face. */
	struct hit h = must_hit(b, v3(0, 0.5, -5), dz, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(b, v3(0, 0.5, -5), dz, &h), 0, 0, -1, 0);
	/* Parallel and outside the slab: a miss however long the ray. */
	assert_false(hits(b, v3(0, 1.5, -5), dz, 0, INFINITY));
	assert_false(hits(b, v3(0, -1.0000001, -5), dz, 0, INFINITY));
	assert_false(hits(b, v3(-3, 0, -5), dz, 0, INFINITY));
	/* Parallel to two slabs at once. */
	h = must_hit(b, v3(0.9, -0.9, 7), v3(0, 0, -2), 0);
	assert_near(h.t, 3, 0);
	/* Parallel to x and y faces, outside in y. */
	assert_false(hits(b, v3(0.9, 1.1, 7), v3(0, 0, -2), 0, INFINITY));
	object_free(b);
}

/* A box flat along an axis has no inside (POV-Ray gives it the whole
 * face): subtracting it from a solid whose face it lies on must change
 * nothing (tests/stability degenerate.pov). */
static void test_box_flat_has_no_inside(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, 0, -1), v3(1, 0, 1), nopos);
	assert_false(object_inside(b, v3(0, 0, 0)));
	assert_false(object_inside(b, v3(1, 0, 1)));
	object_free(b);
	b = box_new(v3(0.5, 0.5, -1), v3(0.5, 0.5, -1), nopos);
	assert_false(object_inside(b, v3(0.5, 0.5, -1)));
	object_free(b);
}

static void test_box_inside_and_on_surface(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -2, -3), v3(1, 2, 3), nopos);
	vec3 o = v3(0, 0, 0);
	struct hit h = must_hit(b, o, v3(1, 0, 0), 0);
	assert_near(h.t, 1, 0);
	assert_vec_near(hit_normal(b, o, v3(1, 0, 0), &h), 1, 0, 0, 0);
	h = must_hit(b, o, v3(0, -1, 0), 0);
	assert_near(h.t, 2, 0);
	assert_vec_near(hit_normal(b, o, v3(0, -1, 0), &h), 0, -1, 0, 0);
	h = must_hit(b, o, v3(0, 0, 0.5), 0);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(b, o, v3(0, 0, 0.5), &h), 0, 0, 1, 0);
	/* On the surface, going in: t = 0 is excluded, the exit is found. */
	h = must_hit(b, v3(0, 0, -3), v3(0, 0, 1), 0);
	assert_near(h.t, 6, 0);
	assert_vec_near(hit_normal(b, v3(0, 0, -3), v3(0, 0, 1), &h), 0, 0, 1, 0);
	/* On the surface, going out: nothing. */
	assert_false(hits(b, v3(0, 0, -3), v3(0, 0, -1), 0, INFINITY));
	assert_false(hits(b, v3(1, 0, 0), v3(1, 0, 0), 0, INFINITY));
	/* Points on the faces are inside, as in POV-Ray 3.7 (its inside()
	 * gives 1 at <1,0,0> and <1,1,1> of box { -1, 1 }). */
	assert_true(object_inside(b, v3(0, 0, 0)));
	assert_true(object_inside(b, v3(0.99, -1.99, 2.99)));
	assert_true(object_inside(b, v3(1, 0, 0)));
	assert_true(object_inside(b, v3(1, -2, 3)));
	assert_false(object_inside(b, v3(1 + 1e-12, 0, 0)));
	assert_false(object_inside(b, v3(0, 2.01, 0)));
	assert_false(object_inside(b, v3(0, 0, -3.5)));
	/* Bounds are the corners. */
	struct aabb bb = object_world_bounds(b);
	assert_vec_near(bb.lo, -1, -2, -3, 0);
	assert_vec_near(bb.hi, 1, 2, 3, 0);
	/* all_hits: in and out, or just out from inside. */
	struct ray r = mkray(v3(-5, 0, 0), v3(1, 0, 0));
	struct hit out[3];
	assert_int_equal(b->ops->all_hits(b, &r, 0, INFINITY, out, 3), 2);
	assert_near(out[0].t, 4, 0);
	assert_near(out[1].t, 6, 0);
	assert_ptr_equal(out[1].obj, b);
	r = mkray(v3(0, 0, 0), v3(1, 0, 0));
	assert_int_equal(b->ops->all_hits(b, &r, 0, INFINITY, out, 3), 1);
	assert_near(out[0].t, 1, 0);
	/* With no hit record, the normal is that of the nearest face. */
	assert_vec_near(object_normal(b, v3(0.2, 1.95, 0), NULL), 0, 1, 0, 0);
	assert_vec_near(object_normal(b, v3(-0.999, 0, 0.5), NULL), -1, 0, 0, 0);
	object_free(b);
}

/* ---- transformed objects ---- */

static void test_transform_translate(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	transform(s, xform_translate(v3(3, 0, 0)));
	assert_true(s->has_xf);
	struct hit h = must_hit(s, v3(3, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(s, v3(3, 0, -5), v3(0, 0, 1), &h), 0, 0, -1, 0);
	assert_false(hits(s, v3(0, 0, -5), v3(0, 0, 1), 0, INFINITY));
	assert_true(object_inside(s, v3(3.5, 0, 0)));
	assert_false(object_inside(s, v3(0, 0, 0)));
	struct aabb b = object_world_bounds(s);
	assert_vec_near(b.lo, 2, -1, -1, 0);
	assert_vec_near(b.hi, 4, 1, 1, 0);
	/* Moving back gives the identity again. */
	transform(s, xform_translate(v3(-3, 0, 0)));
	assert_false(s->has_xf);
	h = must_hit(s, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	object_free(s);
}

static void test_transform_nonuniform_scale(void **state)
{
	(void)state;
	/* scale <2,1,1>: the ellipsoid x^2/4 + y^2 + z^2 = 1. */
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	transform(s, xform_scale(v3(2, 1, 1)));
	struct hit h = must_hit(s, v3(-5, 0, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(s, v3(-5, 0, 0), v3(1, 0, 0), &h), -1, 0, 0, 0);
	h = must_hit(s, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 0);
	/* The world parameter does not depend on the direction's length. */
	h = must_hit(s, v3(-5, 0, 0), v3(0.5, 0, 0), 0);
	assert_near(h.t, 6, 0);
	/* At p = <sqrt 2, sqrt(1/2), 0> the normal is (x/4, y, z) ~ <1,2,0>,
	 * not the scaled object normal. Come in along it from 3 away. */
	vec3 p = v3(sqrt(2), sqrt(0.5), 0), n = v3_norm(v3(1, 2, 0));
	vec3 org = v3_madd(p, n, 3), dir = v3_neg(n);
	h = must_hit(s, org, dir, 0);
	assert_near(h.t, 3, 1e-14);
	vec3 hn = hit_normal(s, org, dir, &h);
	assert_vec_near(hn, n.x, n.y, n.z, 1e-14);
	/* An oblique ray in a scaled frame: y = 0.5 across z = 0 from x = -5
	 * meets x = -2 sqrt(0.75) at t = 5 - sqrt 3. */
	h = must_hit(s, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 5 - sqrt(3), 1e-14);
	hn = hit_normal(s, v3(-5, 0.5, 0), v3(1, 0, 0), &h);
	/* (x/4, y, z) = (-sqrt(0.75)/2, 0.5, 0), normalised. */
	vec3 ex = v3_norm(v3(-sqrt(0.75) / 2, 0.5, 0));
	assert_vec_near(hn, ex.x, ex.y, ex.z, 1e-14);
	assert_true(object_inside(s, v3(1.9, 0, 0)));
	assert_false(object_inside(s, v3(0, 1.1, 0)));
	struct aabb b = object_world_bounds(s);
	assert_vec_near(b.lo, -2, -1, -1, 0);
	assert_vec_near(b.hi, 2, 1, 1, 0);
	object_free(s);

	/* A box scaled by <1,3,0.5>: the y faces move to +-3 and their normals
	 * stay unit. */
	struct object *bx = box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos);
	transform(bx, xform_scale(v3(1, 3, 0.5)));
	h = must_hit(bx, v3(0, 10, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 7, 1e-14); /* 1/3 is inexact */
	assert_vec_near(hit_normal(bx, v3(0, 10, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	h = must_hit(bx, v3(0, 0, -10), v3(0, 0, 1), 0);
	assert_near(h.t, 9.5, 0);
	assert_vec_near(hit_normal(bx, v3(0, 0, -10), v3(0, 0, 1), &h), 0, 0, -1, 0);
	object_free(bx);
}

static void test_transform_rotate(void **state)
{
	(void)state;
	/* Box [0,2]x[-1,1]x[-1,1] turned 90 about z: [-1,1]x[0,2]x[-1,1]. */
	struct object *b = box_new(v3(0, -1, -1), v3(2, 1, 1), nopos);
	transform(b, xform_rotate(v3(0, 0, 90)));
	struct hit h = must_hit(b, v3(0, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 0);
	assert_vec_near(hit_normal(b, v3(0, 5, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	h = must_hit(b, v3(5, 1, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(b, v3(5, 1, 0), v3(-1, 0, 0), &h), 1, 0, 0, 0);
	assert_false(hits(b, v3(5, -0.5, 0), v3(-1, 0, 0), 0, INFINITY));
	assert_true(object_inside(b, v3(0, 1.5, 0)));
	assert_false(object_inside(b, v3(1.5, 0.5, 0)));
	struct aabb bb = object_world_bounds(b);
	assert_vec_near(bb.lo, -1, 0, -1, 0);
	assert_vec_near(bb.hi, 1, 2, 1, 0);
	object_free(b);

	/* 45 degrees about y: a unit cube's corner edge points along -z...
	 * its bounds widen to sqrt 2 in x and z, and a ray down z meets the
	 * vertical edge at z = -sqrt 2. */
	b = box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos);
	transform(b, xform_rotate(v3(0, 45, 0)));
	h = must_hit(b, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 5 - sqrt(2), 1e-15);
	h = must_hit(b, v3(0.5, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 5 - (sqrt(2) - 0.5), 1e-15);
	vec3 n = hit_normal(b, v3(0.5, 0, -5), v3(0, 0, 1), &h);
	assert_vec_near(n, sqrt(0.5), 0, -sqrt(0.5), 1e-15);
	bb = object_world_bounds(b);
	assert_vec_near(bb.lo, -sqrt(2), -1, -sqrt(2), 1e-15);
	assert_vec_near(bb.hi, sqrt(2), 1, sqrt(2), 1e-15);
	object_free(b);
}

static void test_transform_chain(void **state)
{
	(void)state;
	/* scale <2,1,1> rotate y*90 translate <0,0,10>: the cube becomes
	 * [-1,1]x[-1,1]x[8,12]. */
	struct object *b = box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos);
	transform(b, xform_scale(v3(2, 1, 1)));
	transform(b, xform_rotate(v3(0, 90, 0)));
	transform(b, xform_translate(v3(0, 0, 10)));
	struct hit h = must_hit(b, v3(0, 0, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 8, 0);
	assert_vec_near(hit_normal(b, v3(0, 0, 0), v3(0, 0, 1), &h), 0, 0, -1, 0);
	h = must_hit(b, v3(5, 0, 11), v3(-1, 0, 0), 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(b, v3(5, 0, 11), v3(-1, 0, 0), &h), 1, 0, 0, 0);
	struct aabb bb = object_world_bounds(b);
	assert_vec_near(bb.lo, -1, -1, 8, 0);
	assert_vec_near(bb.hi, 1, 1, 12, 0);
	assert_true(object_inside(b, v3(0, 0, 11.5)));
	assert_false(object_inside(b, v3(1.5, 0, 10)));
	/* all_hits works in object space on the carried ray: same t. */
	struct ray r = mkray(v3(0, 0, 0), v3(0, 0, 1));
	struct ray lr = mkray(mat_point(&b->xf.inv, r.org), mat_dir(&b->xf.inv, r.dir));
	struct hit out[2];
	assert_int_equal(b->ops->all_hits(b, &lr, 0, INFINITY, out, 2), 2);
	assert_near(out[0].t, 8, 0);
	assert_near(out[1].t, 12, 0);
	object_free(b);

	/* Transforms apply after the current one: translate x then scale 2
	 * puts the centre at <2,0,0> with radius 2. */
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	transform(s, xform_translate(v3(1, 0, 0)));
	transform(s, xform_scale(v3(2, 2, 2)));
	h = must_hit(s, v3(2, 0, -10), v3(0, 0, 1), 0);
	assert_near(h.t, 8, 0);
	bb = object_world_bounds(s);
	assert_vec_near(bb.lo, 0, -2, -2, 0);
	assert_vec_near(bb.hi, 4, 2, 2, 0);
	object_free(s);
}

static void test_transform_plane(void **state)
{
	(void)state;
	/* The floor turned 90 about z: the normal <0,1,0> goes to <-1,0,0>. */
	struct object *p = plane_new(v3(0, 1, 0), 0, nopos);
	transform(p, xform_rotate(v3(0, 0, 90)));
	struct hit h = must_hit(p, v3(5, 0, 0), v3(-1, 0, 0), 0);
	assert_near(h.t, 5, 0);
	assert_vec_near(hit_normal(p, v3(5, 0, 0), v3(-1, 0, 0), &h), -1, 0, 0, 0);
	assert_true(object_inside(p, v3(5, 0, 0)));
	assert_false(object_inside(p, v3(-5, 0, 0)));
	assert_false(hits(p, v3(5, 0, 0), v3(0, 1, 1), 0, INFINITY));
	/* Still unbounded. */
	assert_false(aabb_is_finite(object_world_bounds(p)));
	object_free(p);
	/* Raised by 3 and squashed: scale y 0.5 moves y = 3 to 1.5; the normal
	 * stays unit. */
	p = plane_new(v3(0, 1, 0), 0, nopos);
	transform(p, xform_translate(v3(0, 3, 0)));
	transform(p, xform_scale(v3(4, 0.5, 4)));
	h = must_hit(p, v3(0, 10, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 8.5, 0);
	assert_vec_near(hit_normal(p, v3(0, 10, 0), v3(0, -1, 0), &h), 0, 1, 0, 0);
	/* A tilted plane under non-uniform scale: x + y = 0 scaled x by 2
	 * becomes x/2 + y = 0, normal ~ <1,2,0>. */
	object_free(p);
	p = plane_new(v3(1, 1, 0), 0, nopos);
	transform(p, xform_scale(v3(2, 1, 1)));
	h = must_hit(p, v3(0, 3, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 3, 1e-15);
	vec3 n = hit_normal(p, v3(0, 3, 0), v3(0, -1, 0), &h);
	vec3 ex = v3_norm(v3(1, 2, 0));
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-15);
	object_free(p);
}

/* ---- BVH ---- */

/* A deterministic uniform number in [lo, hi). */
static double urand(uint32_t i, uint32_t k, double lo, double hi)
{
	return lo + (hi - lo) * hash_uniform(i, k, 0, 77);
}

struct scene_fixture {
	struct object **objs;
	size_t n;
	struct bvh *bvh;
};

static void make_scene(struct scene_fixture *sc, size_t n)
{
	sc->n = n;
	sc->objs = calloc(n, sizeof *sc->objs);
	assert_non_null(sc->objs);
	for (size_t i = 0; i < n; i++) {
		uint32_t k = (uint32_t)i;
		vec3 c = v3(urand(k, 0, -10, 10), urand(k, 1, -10, 10), urand(k, 2, -10, 10));
		double r = urand(k, 3, 0.05, 0.8);
		struct object *o;
		switch (i % 4) {
		case 0:
		case 1:
			o = sphere_new(c, r, nopos);
			break;
		case 2:
			/* A squashed, turned sphere placed by transforms. */
			o = sphere_new(v3(0, 0, 0), r, nopos);
			transform(o, xform_scale(v3(1, 0.5, 1.5)));
			transform(o, xform_rotate(v3(urand(k, 4, 0, 360), urand(k, 5, 0, 360), 0)));
			transform(o, xform_translate(c));
			break;
		default:
			o = box_new(v3_sub(c, v3(r, r / 2, r)), v3_add(c, v3(r / 2, r, r)), nopos);
			break;
		}
		if (i % 7 == 0)
			o->flags |= OBJ_NO_SHADOW;
		o->id = (unsigned)i;
		o->bounds = object_world_bounds(o);
		assert_true(aabb_is_finite(o->bounds));
		sc->objs[i] = o;
	}
	sc->bvh = bvh_build(sc->objs, n);
	assert_non_null(sc->bvh);
}

static void free_scene(struct scene_fixture *sc)
{
	bvh_free(sc->bvh);
	for (size_t i = 0; i < sc->n; i++)
		object_free(sc->objs[i]);
	free(sc->objs);
}

static bool brute_closest(const struct scene_fixture *sc, const struct ray *r, double tmin, double tmax,
                          unsigned skip, struct hit *best)
{
	bool found = false;
	for (size_t i = 0; i < sc->n; i++) {
		struct hit h;
		if (sc->objs[i]->flags & skip)
			continue;
		if (object_intersect(sc->objs[i], r, tmin, tmax, &h)) {
			tmax = h.t;
			*best = h;
			found = true;
		}
	}
	return found;
}

/* The i-th test ray: random origins in and around the scene, and every
 * eighth direction along an axis (zero components exercise the infinite
 * reciprocals in the node test). */
static struct ray test_ray(uint32_t i)
{
	vec3 o = v3(urand(i, 10, -15, 15), urand(i, 11, -15, 15), urand(i, 12, -15, 15));
	vec3 d = v3(urand(i, 13, -1, 1), urand(i, 14, -1, 1), urand(i, 15, -1, 1));
	if (i % 8 == 0) {
		int axis = (int)(i / 8 % 3);
		double s = i / 24 % 2 ? -1 : 1;
		d = v3(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
		/* Aim it at the scene's middle part so it hits something. */
		o = v3(axis == 0 ? -15 * s : urand(i, 16, -8, 8), axis == 1 ? -15 * s : urand(i, 17, -8, 8),
		       axis == 2 ? -15 * s : urand(i, 18, -8, 8));
	} else if (i % 3 == 0) {
		/* Aim at a random point in the scene. */
		vec3 target = v3(urand(i, 19, -10, 10), urand(i, 20, -10, 10), urand(i, 21, -10, 10));
		d = v3_scale(v3_sub(target, o), urand(i, 22, 0.1, 3));
	}
	return mkray(o, d);
}

static void test_bvh_matches_brute_force(void **state)
{
	(void)state;
	struct scene_fixture sc;
	make_scene(&sc, 400);
	assert_true(bvh_node_count(sc.bvh) > 1);
	int nhits = 0;
	for (uint32_t i = 0; i < 4000; i++) {
		struct ray r = test_ray(i);
		for (unsigned skip = 0; skip <= OBJ_NO_SHADOW; skip += OBJ_NO_SHADOW) {
			struct hit hb = {.t = 0, .part = -1}, hf = {.t = 0, .part = -1};
			bool fb = bvh_intersect(sc.bvh, &r, 1e-6, INFINITY, skip, &hb, NULL);
			bool ff = brute_closest(&sc, &r, 1e-6, INFINITY, skip, &hf);
			if (fb != ff)
				fail_msg("ray %u skip %u: bvh %s, brute force %s", i, skip, fb ? "hit" : "missed",
				         ff ? "hit" : "missed");
			if (!ff)
				continue;
			nhits++;
			if (hb.obj != hf.obj || hb.t != hf.t)
				fail_msg("ray %u skip %u: bvh hit object %u at t=%.17g, brute force object %u at t=%.17g",
				         i, skip, hb.obj->id, hb.t, hf.obj->id, hf.t);
			assert_int_equal(hb.part, hf.part);
			assert_true((hb.obj->flags & skip) == 0);
		}
	}
	/* The test means something only if many rays hit. */
	assert_true(nhits > 2000);
	free_scene(&sc);
}

static void test_bvh_tmax_and_occluded(void **state)
{
	(void)state;
	struct scene_fixture sc;
	make_scene(&sc, 300);
	int blocked = 0, clear = 0;
	for (uint32_t i = 0; i < 4000; i++) {
		struct ray r = test_ray(i);
		double tmax = urand(i, 30, 0.5, 30) / fmax(v3_len(r.dir), 1e-300);
		unsigned skip = i % 2 ? OBJ_NO_SHADOW : 0;
		/* Closest hit within a finite tmax. */
		struct hit hb, hf;
		bool fb = bvh_intersect(sc.bvh, &r, 1e-6, tmax, skip, &hb, NULL);
		bool ff = brute_closest(&sc, &r, 1e-6, tmax, skip, &hf);
		assert_int_equal(fb, ff);
		if (ff) {
			assert_ptr_equal(hb.obj, hf.obj);
			assert_true(hb.t == hf.t);
			assert_true(hb.t < tmax);
		}
		/* Any hit: the same answer, and the blocker really blocks. */
		const struct object *blocker = NULL;
		bool ob = bvh_occluded(sc.bvh, &r, 1e-6, tmax, skip, &blocker);
		if (ob != ff)
			fail_msg("ray %u: bvh_occluded %d, brute force %d", i, ob, ff);
		if (ob) {
			struct hit h;
			assert_non_null(blocker);
			assert_true((blocker->flags & skip) == 0);
			assert_true(object_intersect(blocker, &r, 1e-6, tmax, &h));
			blocked++;
		} else {
			clear++;
		}
	}
	if (!(blocked > 300 && clear > 300))
		fail_msg("%d blocked, %d clear", blocked, clear);
	free_scene(&sc);
}

static void test_bvh_small(void **state)
{
	(void)state;
	/* Empty. */
	struct bvh *b = bvh_build(NULL, 0);
	struct ray r = mkray(v3(0, 0, -5), v3(0, 0, 1));
	struct hit h;
	const struct object *blocker = NULL;
	assert_false(bvh_intersect(b, &r, 0, INFINITY, 0, &h, NULL));
	assert_false(bvh_occluded(b, &r, 0, INFINITY, 0, &blocker));
	bvh_free(b);
	/* One object, and one skipped by its flag. */
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	s->bounds = object_world_bounds(s);
	struct object *objs[1] = {s};
	b = bvh_build(objs, 1);
	assert_true(bvh_intersect(b, &r, 0, INFINITY, 0, &h, NULL));
	assert_ptr_equal(h.obj, s);
	assert_near(h.t, 4, 0);
	assert_true(bvh_occluded(b, &r, 0, INFINITY, 0, &blocker));
	assert_ptr_equal(blocker, s);
	assert_false(bvh_occluded(b, &r, 0, 3.5, 0, &blocker));
	s->flags |= OBJ_NO_SHADOW;
	assert_false(bvh_occluded(b, &r, 0, INFINITY, OBJ_NO_SHADOW, &blocker));
	assert_false(bvh_intersect(b, &r, 0, INFINITY, OBJ_NO_SHADOW, &h, NULL));
	assert_true(bvh_intersect(b, &r, 0, INFINITY, OBJ_NO_IMAGE, &h, NULL));
	bvh_free(b);
	object_free(s);
	/* Many objects sharing one centroid still build and trace. */
	struct object *same[20];
	for (int i = 0; i < 20; i++) {
		same[i] = sphere_new(v3(0, 0, 0), 0.1 + 0.05 * i, nopos);
		same[i]->bounds = object_world_bounds(same[i]);
	}
	b = bvh_build(same, 20);
	assert_true(bvh_intersect(b, &r, 0, INFINITY, 0, &h, NULL));
	assert_ptr_equal(h.obj, same[19]);
	assert_near(h.t, 5 - (0.1 + 0.05 * 19), 1e-15);
	/* From the centre outward the smallest comes first. */
	r = mkray(v3(0, 0, 0), v3(1, 0, 0));
	assert_true(bvh_intersect(b, &r, 0, INFINITY, 0, &h, NULL));
	assert_ptr_equal(h.obj, same[0]);
	assert_near(h.t, 0.1, 1e-15);
	bvh_free(b);
	for (int i = 0; i < 20; i++)
		object_free(same[i]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sphere_hit_miss),
		cmocka_unit_test(test_sphere_grazing),
		cmocka_unit_test(test_sphere_inside_and_on_surface),
		cmocka_unit_test(test_sphere_all_hits),
		cmocka_unit_test(test_sphere_inside_bounds),
		cmocka_unit_test(test_sphere_far_from_origin),
		cmocka_unit_test(test_sphere_tiny),
		cmocka_unit_test(test_plane),
		cmocka_unit_test(test_plane_normal_and_distance),
		cmocka_unit_test(test_box_hit_miss),
		cmocka_unit_test(test_box_parallel),
		cmocka_unit_test(test_box_inside_and_on_surface),
		cmocka_unit_test(test_box_flat_has_no_inside),
		cmocka_unit_test(test_transform_translate),
		cmocka_unit_test(test_transform_nonuniform_scale),
		cmocka_unit_test(test_transform_rotate),
		cmocka_unit_test(test_transform_chain),
		cmocka_unit_test(test_transform_plane),
		cmocka_unit_test(test_bvh_matches_brute_force),
		cmocka_unit_test(test_bvh_tmax_and_occluded),
		cmocka_unit_test(test_bvh_small),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

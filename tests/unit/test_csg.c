/* test_csg.c: unit tests for CSG (src/geom/csg.h) and the modifiers every
 * object has (clipped_by, bounded_by, inverse, transforms of a CSG). The
 * children are spheres, boxes and planes, whose answers are analytic; a
 * CSG after prepare (its own BVH) must agree exactly with the same CSG
 * before it (children scanned one by one). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/csg.h"
#include "geom/shapes.h"
#include "math/hash.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"

static const struct srcpos nopos = {0, 0, 0};

/* Every crossing of o along org + t dir for t > 0, by repeated closest
 * hits; returns how many (at most max). */
static int crossings(const struct object *o, vec3 org, vec3 dir, double *t, int max)
{
	struct ray r = {org, dir};
	int n = 0;
	double tmin = 0;
	struct hit h;
	while (n < max && object_intersect(o, &r, tmin, INFINITY, &h)) {
		t[n++] = h.t;
		tmin = h.t;
	}
	return n;
}

static struct object *two_spheres(enum csg_kind k)
{
	/* Unit spheres at x = -0.5 and x = 0.5: they overlap on [-0.5, 0.5]. */
	struct object *c = csg_new(k, nopos);
	csg_add(c, sphere_new(v3(-0.5, 0, 0), 1, nopos));
	csg_add(c, sphere_new(v3(0.5, 0, 0), 1, nopos));
	return c;
}

static void test_union(void **state)
{
	(void)state;
	struct object *c = two_spheres(CSG_UNION);
	double t[8];
	/* Along x from -5: every surface of both spheres, inner ones too. */
	assert_int_equal(crossings(c, v3(-5, 0, 0), v3(1, 0, 0), t, 8), 4);
	assert_near(t[0], 3.5, 1e-12);
	assert_near(t[1], 4.5, 1e-12);
	assert_near(t[2], 5.5, 1e-12);
	assert_near(t[3], 6.5, 1e-12);
	assert_true(object_inside(c, v3(-1.2, 0, 0)));
	assert_true(object_inside(c, v3(1.2, 0, 0)));
	assert_false(object_inside(c, v3(0, 1.2, 0)));
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -1.5, -1, -1, 0);
	assert_vec_near(b.hi, 1.5, 1, 1, 0);
	object_free(c);
}

static void test_merge(void **state)
{
	(void)state;
	struct object *c = two_spheres(CSG_MERGE);
	double t[8];
	/* Only the outer surfaces remain. */
	assert_int_equal(crossings(c, v3(-5, 0, 0), v3(1, 0, 0), t, 8), 2);
	assert_near(t[0], 3.5, 1e-12);
	assert_near(t[1], 6.5, 1e-12);
	/* The hit names the leaf sphere it found. */
	struct ray r = {v3(5, 0, 0), v3(-1, 0, 0)};
	struct hit h;
	assert_true(object_intersect(c, &r, 0, INFINITY, &h));
	struct object **kids;
	assert_int_equal(c->ops->children(c, &kids), 2);
	assert_ptr_equal(h.obj, kids[1]);
	object_free(c);
}

static void test_intersection(void **state)
{
	(void)state;
	struct object *c = two_spheres(CSG_INTERSECTION);
	double t[8];
	/* The lens between x = -0.5 and x = 0.5. */
	assert_int_equal(crossings(c, v3(-5, 0, 0), v3(1, 0, 0), t, 8), 2);
	assert_near(t[0], 4.5, 1e-12);
	assert_near(t[1], 5.5, 1e-12);
	assert_true(object_inside(c, v3(0, 0, 0)));
	assert_false(object_inside(c, v3(-1, 0, 0)));
	/* A ray through one sphere only misses. */
	assert_int_equal(crossings(c, v3(-1.2, -5, 0), v3(0, 1, 0), t, 8), 0);
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, -0.5, -1, -1, 0);
	assert_vec_near(b.hi, 0.5, 1, 1, 0);
	object_free(c);
}

static void test_difference(void **state)
{
	(void)state;
	/* A box with a spherical bite out of its +x face. */
	struct object *c = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(c, box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos));
	csg_add(c, sphere_new(v3(1, 0, 0), 0.5, nopos));
	double t[8];
	/* Along x through the bite: box face at -1, then the sphere's surface
	 * at x = 0.5 (seen from inside the box). */
	assert_int_equal(crossings(c, v3(-5, 0, 0), v3(1, 0, 0), t, 8), 2);
	assert_near(t[0], 4, 1e-12);
	assert_near(t[1], 5.5, 1e-12);
	/* Beside the bite the +x face is there. */
	assert_int_equal(crossings(c, v3(-5, 0.9, 0), v3(1, 0, 0), t, 8), 2);
	assert_near(t[1], 6, 1e-12);
	assert_false(object_inside(c, v3(0.9, 0, 0)));
	assert_true(object_inside(c, v3(0.4, 0, 0)));
	/* The normal on the bite's surface points out of the solid's
	 * material, that is into the bite: object_normal gives the sphere's
	 * outward normal, -x at x = 0.5. */
	struct ray r = {v3(-5, 0, 0), v3(1, 0, 0)};
	struct hit h;
	assert_true(object_intersect(c, &r, 4.5, INFINITY, &h));
	vec3 n = object_normal(h.obj, v3_madd(r.org, r.dir, h.t), &h);
	assert_vec_near(n, -1, 0, 0, 1e-15);
	object_free(c);
}

static void test_transform_and_copy(void **state)
{
	(void)state;
	struct object *c = two_spheres(CSG_MERGE);
	struct xform t = xform_translate(v3(0, 10, 0));
	object_transform(c, &t);
	struct object *d = object_copy(c);
	struct xform s = xform_scale(v3(2, 2, 2));
	object_transform(d, &s);
	double tt[4];
	/* c moved up by 10; d then scaled about the origin. */
	assert_int_equal(crossings(c, v3(-5, 10, 0), v3(1, 0, 0), tt, 4), 2);
	assert_near(tt[0], 3.5, 1e-12);
	assert_int_equal(crossings(d, v3(-5, 20, 0), v3(1, 0, 0), tt, 4), 2);
	assert_near(tt[0], 2, 1e-12);
	assert_int_equal(crossings(c, v3(-5, 20, 0), v3(1, 0, 0), tt, 4), 0);
	object_free(c);
	object_free(d);
}

static void test_clip_and_bound(void **state)
{
	(void)state;
	/* A sphere clipped by a box around its upper half: a cup seen from
	 * below is open. */
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	s->clip = box_new(v3(-2, 0, -2), v3(2, 2, 2), nopos);
	double t[4];
	assert_int_equal(crossings(s, v3(0, -5, 0), v3(0, 1, 0), t, 4), 1);
	assert_near(t[0], 6, 1e-12);
	assert_int_equal(crossings(s, v3(0.5, -5, 0), v3(0, 0, 1), t, 4), 0);
	assert_false(object_inside(s, v3(0, -0.5, 0)));
	assert_true(object_inside(s, v3(0, 0.5, 0)));
	/* POV-Ray keeps the smaller box by volume, the sphere's 8 against
	 * the clip's 16; it does not cut one with the other. */
	struct aabb b = object_world_bounds(s);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	assert_vec_near(b.hi, 1, 1, 1, 0);
	/* A bound smaller by volume (7.2) wins even where it is wider. */
	s->bound = box_new(v3(-0.1, -3, -3), v3(0.1, 3, 3), nopos);
	b = object_world_bounds(s);
	assert_vec_near(b.lo, -0.1, -3, -3, 0);
	assert_vec_near(b.hi, 0.1, 3, 3, 0);
	/* Transforms move the clip with the object. */
	struct xform tr = xform_translate(v3(0, 0, 3));
	object_transform(s, &tr);
	assert_int_equal(crossings(s, v3(0, -5, 3), v3(0, 1, 0), t, 4), 1);
	object_free(s);

	/* bounded_by: rays that miss the bound skip the object. */
	struct object *q = sphere_new(v3(0, 0, 0), 1, nopos);
	q->bound = box_new(v3(-0.5, -0.5, -0.5), v3(0.5, 0.5, 0.5), nopos);
	assert_int_equal(crossings(q, v3(0.8, 0, -5), v3(0, 0, 1), t, 4), 0);
	assert_int_equal(crossings(q, v3(0, 0, -5), v3(0, 0, 1), t, 4), 2);
	object_free(q);
}

static void test_inverse(void **state)
{
	(void)state;
	/* Intersection with an inverse sphere is a difference. */
	struct object *c = csg_new(CSG_INTERSECTION, nopos);
	csg_add(c, box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos));
	struct object *s = sphere_new(v3(1, 0, 0), 0.5, nopos);
	s->flags |= OBJ_INVERSE;
	csg_add(c, s);
	double t[4];
	assert_int_equal(crossings(c, v3(-5, 0, 0), v3(1, 0, 0), t, 4), 2);
	assert_near(t[1], 5.5, 1e-12);
	object_free(c);
}

/* Extents measured with POV-Ray's min_extent/max_extent: axis-aligned
 * planes cut an intersection's box (also inverted, in a difference, and
 * moved by a translation or a 90-degree rotation); a box left unbounded on
 * any axis, or empty, is infinite. */
static void test_plane_extents(void **state)
{
	(void)state;
	struct object *cube = csg_new(CSG_INTERSECTION, nopos);
	for (int a = 0; a < 3; a++)
		for (int s = -1; s <= 1; s += 2)
			csg_add(cube, plane_new(v3(a == 0 ? s : 0, a == 1 ? s : 0, a == 2 ? s : 0), 1, nopos));
	struct xform sc = xform_scale(v3(2, 2, 2)), tr = xform_translate(v3(1, 1, 1));
	object_transform(cube, &sc);
	object_transform(cube, &tr);
	struct aabb b = object_world_bounds(cube);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	assert_vec_near(b.hi, 3, 3, 3, 0);
	object_free(cube);

	struct object *slab = csg_new(CSG_INTERSECTION, nopos);
	csg_add(slab, plane_new(v3(0, 1, 0), 1, nopos));
	csg_add(slab, plane_new(v3(0, -1, 0), 1, nopos));
	assert_false(aabb_is_finite(object_world_bounds(slab)));
	object_free(slab);

	struct object *d = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(d, box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos));
	struct object *p = plane_new(v3(0, 1, 0), 0.5, nopos);
	struct xform rz = xform_rotate(v3(0, 0, 90));
	object_transform(p, &rz); /* the plane x > -0.5; subtracted: x < -0.5 */
	csg_add(d, p);
	b = object_world_bounds(d);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	assert_vec_near(b.hi, -0.5, 1, 1, 1e-15);
	object_free(d);

	/* Rotated as a whole, the cube keeps its box, rotated (POV-Ray:
	 * x, z in +-1.414214); rotated back, the box of that box (+-2). */
	cube = csg_new(CSG_INTERSECTION, nopos);
	for (int a = 0; a < 3; a++)
		for (int s = -1; s <= 1; s += 2)
			csg_add(cube, plane_new(v3(a == 0 ? s : 0, a == 1 ? s : 0, a == 2 ? s : 0), 1, nopos));
	struct xform ry = xform_rotate(v3(0, 45, 0)), ryb = xform_rotate(v3(0, -45, 0));
	object_transform(cube, &ry);
	b = object_world_bounds(cube);
	assert_vec_near(b.lo, -sqrt(2), -1, -sqrt(2), 1e-12);
	assert_vec_near(b.hi, sqrt(2), 1, sqrt(2), 1e-12);
	struct object *cc = object_copy(cube);
	object_transform(cube, &ryb);
	b = object_world_bounds(cube);
	assert_vec_near(b.lo, -2, -1, -2, 1e-12);
	assert_vec_near(b.hi, 2, 1, 2, 1e-12);
	b = object_world_bounds(cc); /* the copy keeps its own box */
	assert_vec_near(b.hi, sqrt(2), 1, sqrt(2), 1e-12);
	object_free(cc);
	object_free(cube);

	struct object *e = csg_new(CSG_INTERSECTION, nopos);
	csg_add(e, sphere_new(v3(0, 0, 0), 1, nopos));
	csg_add(e, plane_new(v3(0, 1, 0), -5, nopos));
	assert_false(aabb_is_finite(object_world_bounds(e)));
	object_free(e);
}

/* A difference of a box and many small spheres: after object_prepare (a
 * BVH over the subtracted children) every ray gives exactly the answer of
 * the unprepared CSG. Likewise for merge and union. */
static void test_prepared_matches_scan(void **state)
{
	(void)state;
	enum csg_kind kinds[] = {CSG_DIFFERENCE, CSG_MERGE, CSG_UNION};
	for (int k = 0; k < 3; k++) {
		struct object *a = csg_new(kinds[k], nopos);
		csg_add(a, box_new(v3(-2, -2, -2), v3(2, 2, 2), nopos));
		for (uint32_t i = 0; i < 200; i++) {
			vec3 c = v3(4 * hash_uniform(i, 0, k, 1) - 2, 4 * hash_uniform(i, 1, k, 1) - 2,
			            4 * hash_uniform(i, 2, k, 1) - 2);
			csg_add(a, sphere_new(c, 0.05 + 0.3 * hash_uniform(i, 3, k, 1), nopos));
		}
		csg_add(a, plane_new(v3(0, 1, 0), -1.5, nopos));
		struct object *b = object_copy(a);
		object_prepare(b);
		for (uint32_t i = 0; i < 2000; i++) {
			vec3 org = v3(10 * hash_uniform(i, 0, k, 2) - 5, 10 * hash_uniform(i, 1, k, 2) - 5, -8);
			vec3 to = v3(4 * hash_uniform(i, 2, k, 2) - 2, 4 * hash_uniform(i, 3, k, 2) - 2,
			             4 * hash_uniform(i, 4, k, 2) - 2);
			struct ray r = {org, v3_sub(to, org)};
			struct hit ha, hb;
			bool fa = object_intersect(a, &r, 0, INFINITY, &ha);
			bool fb = object_intersect(b, &r, 0, INFINITY, &hb);
			assert_int_equal(fa, fb);
			if (fa)
				assert_near(ha.t, hb.t, 0);
			assert_int_equal(object_inside(a, to), object_inside(b, to));
		}
		object_free(a);
		object_free(b);
	}
}

/* The union of two spheres radius 0.9 at x = -0.5 and 0.5. */
static struct object *lens_union(void)
{
	struct object *u = csg_new(CSG_UNION, nopos);
	csg_add(u, sphere_new(v3(-0.5, 0, 0), 0.9, nopos));
	csg_add(u, sphere_new(v3(0.5, 0, 0), 0.9, nopos));
	return u;
}

/* The closest hit's y along -y from (0.01, 5, 0.03), before and after
 * object_prepare; NAN for a miss. */
static double hit_y_down(struct object *o)
{
	struct ray r = {v3(0.01, 5, 0.03), v3(0, -1, 0)};
	struct hit h, hp;
	double y = NAN;
	if (object_intersect(o, &r, 0, INFINITY, &h))
		y = 5 - h.t;
	struct object *c = object_copy(o);
	object_prepare(c);
	bool f = object_intersect(c, &r, 0, INFINITY, &hp);
	assert_int_equal(f, !isnan(y));
	if (f)
		assert_near(5 - hp.t, y, 1e-12);
	object_free(c);
	return y;
}

/* difference { sphere { 0, 1.5 } union { sphere { <-0.5,0,0>, 0.9 }
 * sphere { <0.5,0,0>, 0.9 } } plane { -y, 0 } }: the ray leaves the left
 * sphere at y = -0.7409 still inside the right one; POV-Ray's trace()
 * gives y = -0.754321 (the right sphere), as it inverts the subtracted
 * union into an intersection of inverted spheres (no inner surfaces). The
 * same with the union inside another union, and inverted by hand. */
static void test_inverted_union(void **state)
{
	(void)state;
	const double right = -0.754321, left = -0.740945; /* POV-Ray, 6 decimals */
	struct object *d = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(d, sphere_new(v3(0, 0, 0), 1.5, nopos));
	csg_add(d, lens_union());
	csg_add(d, plane_new(v3(0, -1, 0), 0, nopos));
	assert_near(hit_y_down(d), right, 1e-6);
	object_free(d);

	/* Nested: union { union { … } sphere { <0,0.5,0>, 0.9 } } subtracted. */
	d = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(d, sphere_new(v3(0, 0, 0), 1.5, nopos));
	struct object *outer = csg_new(CSG_UNION, nopos);
	csg_add(outer, lens_union());
	csg_add(outer, sphere_new(v3(0, 0.5, 0), 0.9, nopos));
	csg_add(d, outer);
	csg_add(d, plane_new(v3(0, -1, 0), 0, nopos));
	assert_near(hit_y_down(d), right, 1e-6);
	object_free(d);

	/* intersection { sphere { 0, 1.5 } object { U inverse } plane { y, 0 } }:
	 * the flag set after the union is built, then csg_settle. */
	struct object *i = csg_new(CSG_INTERSECTION, nopos);
	csg_add(i, sphere_new(v3(0, 0, 0), 1.5, nopos));
	struct object *u = lens_union();
	csg_add(i, u);
	csg_add(i, plane_new(v3(0, 1, 0), 0, nopos));
	u->flags ^= OBJ_INVERSE;
	csg_settle(i);
	assert_near(hit_y_down(i), right, 1e-6);
	object_free(i);

	/* An inverted intersection keeps its crossings (it becomes a merge of
	 * inverted children): the lens's boundary at the left sphere. */
	d = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(d, sphere_new(v3(0, 0, 0), 1.5, nopos));
	struct object *lens = csg_new(CSG_INTERSECTION, nopos);
	csg_add(lens, sphere_new(v3(-0.5, 0, 0), 0.9, nopos));
	csg_add(lens, sphere_new(v3(0.5, 0, 0), 0.9, nopos));
	csg_add(d, lens);
	csg_add(d, plane_new(v3(0, -1, 0), 0, nopos));
	assert_near(hit_y_down(d), left, 1e-6);
	object_free(d);
}

/* From inside both spheres along +x: a union shows the left sphere's inner
 * surface at x = 0.4; inverted (once or twice: a merge) it does not, and
 * the hit is at x = 1.4 (POV-Ray: 0.399722 and 1.399722 from
 * <0,0.01,0.02>). An inverted union must not be split into the scene. */
static void test_inverted_union_alone(void **state)
{
	(void)state;
	struct ray r = {v3(0, 0, 0), v3(1, 0, 0)};
	struct hit h;
	struct object *u = lens_union();
	csg_settle(u);
	assert_true(object_intersect(u, &r, 0, INFINITY, &h));
	assert_near(h.t, 0.4, 1e-12);
	assert_true(csg_splittable(u));
	u->flags ^= OBJ_INVERSE;
	csg_settle(u);
	assert_true(object_intersect(u, &r, 0, INFINITY, &h));
	assert_near(h.t, 1.4, 1e-12);
	assert_true(h.inverted);
	u->flags ^= OBJ_INVERSE;
	csg_settle(u);
	assert_true(object_intersect(u, &r, 0, INFINITY, &h));
	assert_near(h.t, 1.4, 1e-12);
	assert_false(h.inverted);
	assert_false(csg_splittable(u));
	/* A copy keeps it. */
	struct object *c = object_copy(u);
	assert_true(object_intersect(c, &r, 0, INFINITY, &h));
	assert_near(h.t, 1.4, 1e-12);
	object_free(c);
	object_free(u);
}

/* union { sphere { 0, 1 inverse } sphere { 3*x, 1 } }: POV-Ray's box is
 * <-1,-1,-1> to <4,1,1> (min_extent), though its inside is everything
 * outside the unit sphere. */
static struct object *loose_union(void)
{
	struct object *u = csg_new(CSG_UNION, nopos);
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	s->flags |= OBJ_INVERSE;
	csg_add(u, s);
	csg_add(u, sphere_new(v3(3, 0, 0), 1, nopos));
	return u;
}

/* A part whose inside reaches beyond its box (loose) keeps its box for
 * intersections, as POV-Ray does, but inside tests after prepare must not
 * cull by it: a point far outside it is still inside the union, so not
 * inside a difference that subtracts it. And as a part of a union, a loose
 * intersection loses the surface outside its box, as in POV-Ray (trace()
 * at <1.5,1.5,-10> along z misses). */
static void test_loose_parts(void **state)
{
	(void)state;
	struct object *u = loose_union();
	struct aabb b = object_world_bounds(u);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	assert_vec_near(b.hi, 4, 1, 1, 0);
	struct object *d = csg_new(CSG_DIFFERENCE, nopos);
	csg_add(d, box_new(v3(-3, -3, -3), v3(3, 3, 3), nopos));
	csg_add(d, u);
	csg_settle(d);
	vec3 p = v3(2.5, 2.5, 2.5);
	assert_false(object_inside(d, p));
	object_prepare(d);
	assert_true(u->loose);
	assert_false(d->loose);
	assert_false(object_inside(d, p));
	assert_true(object_inside(d, v3(0.5, 0, 0)));
	object_free(d);

	struct object *i = csg_new(CSG_INTERSECTION, nopos);
	csg_add(i, box_new(v3(-2, -2, -2), v3(2, 2, 2), nopos));
	csg_add(i, loose_union());
	b = object_world_bounds(i);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	assert_vec_near(b.hi, 2, 1, 1, 0);
	struct object *top = csg_new(CSG_UNION, nopos);
	csg_add(top, i);
	csg_add(top, sphere_new(v3(10, 0, 0), 1, nopos));
	object_prepare(top);
	double t[4];
	assert_int_equal(crossings(top, v3(1.5, 1.5, -10), v3(0, 0, 1), t, 4), 0);
	/* A ray that meets the box finds every crossing, also outside it. */
	assert_int_equal(crossings(top, v3(0.5, 0.5, -10), v3(0, 0, 1), t, 4), 4);
	assert_near(t[0], 8, 1e-12);
	assert_near(t[3], 12, 1e-12);
	assert_true(object_inside(top, v3(1.5, 1.5, 1.5)));
	object_free(top);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_union),
		cmocka_unit_test(test_merge),
		cmocka_unit_test(test_intersection),
		cmocka_unit_test(test_difference),
		cmocka_unit_test(test_transform_and_copy),
		cmocka_unit_test(test_clip_and_bound),
		cmocka_unit_test(test_inverse),
		cmocka_unit_test(test_plane_extents),
		cmocka_unit_test(test_prepared_matches_scan),
		cmocka_unit_test(test_inverted_union),
		cmocka_unit_test(test_inverted_union_alone),
		cmocka_unit_test(test_loose_parts),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

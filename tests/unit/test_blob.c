/* test_blob.c: unit tests for the blob (src/geom/blob.c). The expected
 * values were measured with POV-Ray 3.7's trace(), inside(), min_extent()
 * and max_extent() on the same blobs, e.g.
 *   #declare B = blob { threshold 0.5 sphere { <0,0,0>, 1, 1 } }
 *   #declare N = <0,0,0>;
 *   #declare P = trace(B, <0.1,0.2,-10>, z, N);
 *   #debug concat(vstr(3,P,",",0,10), " ", vstr(3,N,",",0,10), "\n")
 * printed to 10 digits (bounds: 8; POV-Ray keeps them in single
 * precision). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/blob.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* One sphere: the surface where (1 - d^2)^2 = 0.5, and POV-Ray's depth
 * tolerance of 0.01 along the world ray. */
static void test_single(void **state)
{
	(void)state;
	struct object *o = blob_new(nopos);
	blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	blob_set_threshold(o, 0.5);
	object_prepare(o);
	check_hit(o, v3(0.1, 0.2, -10), v3(0, 0, 1), v3(0.1, 0.2, -0.4928419816),
	          v3(0.1847759065, 0.3695518130, -0.9106532391));
	/* From inside: the far side, the normal still outward. */
	check_hit(o, v3(0.1, 0.2, 0.4), v3(0, 0, 1), v3(0.1, 0.2, 0.4928419816),
	          v3(0.1847759065, 0.3695518130, 0.9106532391));
	double s = 0.49284198158;
	assert_true(hits(o, v3(0.1, 0.2, s - 0.0101), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(o, v3(0.1, 0.2, s - 0.0099), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(o, v3(0.1, 0.2, s - 0.0049), v3(0, 0, 2), 0, INFINITY));
	assert_true(object_inside(o, v3(0.54, 0, 0)));
	assert_false(object_inside(o, v3(0.55, 0, 0)));
	check_box(o, v3(-1, -1, -1), v3(1, 1, 1));
	object_free(o);
	/* Scaled by 2, the tolerance stays 0.01 in world units. */
	o = blob_new(nopos);
	blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	blob_set_threshold(o, 0.5);
	transform(o, xform_scale(v3(2, 2, 2)));
	object_prepare(o);
	assert_true(hits(o, v3(0.2, 0.4, 2 * s - 0.0101), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(o, v3(0.2, 0.4, 2 * s - 0.0099), v3(0, 0, 1), 0, INFINITY));
	object_free(o);
}

/* The manual's three-component blob. */
static void test_manual(void **state)
{
	(void)state;
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *o = blob_new(nopos);
		blob_set_threshold(o, 0.6);
		blob_add_sphere(o, v3(.75, 0, 0), 1, 1);
		blob_add_sphere(o, v3(-.375, .64952, 0), 1, 1);
		blob_add_sphere(o, v3(-.375, -.64952, 0), 1, 1);
		blob_set_sturm(o, sturm);
		object_prepare(o);
		check_hit(o, v3(0.1, 0.2, -10), v3(0, 0, 1), v3(0.1, 0.2, -0.0914097526),
		          v3(-0.3415428915, -0.6830804353, -0.6455614395));
		check_hit(o, v3(0.31, -0.2, -10), v3(0, 0, 1), v3(0.31, -0.2, -0.2131939096),
		          v3(-0.4975740073, -0.0681035671, -0.8647438993));
		check_hit(o, v3(-5, 0.1, 0.2), v3(1, 0, 0), v3(0.3003464037, 0.1, 0.2),
		          v3(-0.7187224333, -0.1301170176, 0.6830136350));
		check_hit(o, v3(-5, 0.3, 0.2), v3(1, 0.1, 0.05), v3(-0.5729433003, 0.7427056700, 0.4213528350),
		          v3(-0.4169275966, 0.1962767993, 0.8874946745));
		check_hit(o, v3(0.3, 5, 0.1), v3(0, -1, 0), v3(0.3, 0.4291842138, 0.1),
		          v3(0.2891286372, 0.7779467908, 0.5578560942));
		/* Asking again from each hit finds the next one, never the same:
		 * a CSG walks the crossings so (a root rounding onto tmin made
		 * it loop). */
		for (int k = 0; k < 50; k++) {
			vec3 org = v3(3 * cos(k * 0.37), 0.7 * sin(k * 0.74), 3 * sin(k * 0.37));
			vec3 dir = v3_add(v3_neg(org), v3(0.1 * sin(k), 0.2 * cos(k), 0));
			struct ray r = mkray(org, dir);
			struct hit h;
			double t = 0;
			int n = 0;
			while (n < 10 && object_intersect(o, &r, t, INFINITY, &h)) {
				assert_true(h.t > t);
				t = h.t;
				n++;
			}
			assert_true(n % 2 == 0 && n <= 6);
			struct hit all[8];
			assert_int_equal(o->ops->all_hits(o, &r, 0, INFINITY, all, 8), n);
		}
		/* The middle is a hole: a ray from there misses. */
		assert_false(hits(o, v3(0, 0, 0), v3(1, 2, 3), 0, INFINITY));
		assert_false(object_inside(o, v3(0, 0, 0)));
		object_free(o);
	}
}

/* A cylinder and a sphere; a negative sphere; ellipsoids. */
static void test_components(void **state)
{
	(void)state;
	struct object *o = blob_new(nopos);
	blob_set_threshold(o, 0.4);
	assert_int_equal(blob_add_cylinder(o, v3(-0.5, 0, 0), v3(0.8, 0.4, 0.1), 0.7, 1), 0);
	blob_add_sphere(o, v3(0.5, -0.3, 0), 0.8, 1);
	object_prepare(o);
	check_hit(o, v3(0.1, 0.2, -10), v3(0, 0, 1), v3(0.1, 0.2, -0.3861128442),
	          v3(-0.0728083398, 0.2019917194, -0.9766771682));
	check_hit(o, v3(0.31, -0.2, -10), v3(0, 0, 1), v3(0.31, -0.2, -0.4437777185),
	          v3(-0.2504989954, -0.0068821958, -0.9680923968));
	check_hit(o, v3(-5, 0.1, 0.2), v3(1, 0, 0), v3(-0.8606893252, 0.1, 0.2),
	          v3(-0.8499244132, 0.2356389152, 0.4712778305));
	check_hit(o, v3(0.3, 5, 0.1), v3(0, -1, 0), v3(0.3, 0.6891426152, 0.1),
	          v3(-0.2981645104, 0.9521110036, 0.0676946204));
	check_hit(o, v3(0, 0, 0), v3(1, 2, 3), v3(0.1551099671, 0.3102199343, 0.4653299014),
	          v3(-0.1399119470, 0.2129662827, 0.9669901807));
	assert_true(object_inside(o, v3(0, 0, 0)));
	assert_int_equal(blob_add_cylinder(o, v3(1, 1, 1), v3(1, 1, 1), 1, 1), -1);
	object_free(o);

	o = blob_new(nopos);
	blob_set_threshold(o, 0.3);
	int c = blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	struct xform t = xform_scale(v3(1.5, 0.6, 1));
	blob_transform_component(o, c, &t, false);
	t = xform_rotate(v3(0, 0, 30));
	blob_transform_component(o, c, &t, true);
	blob_add_sphere(o, v3(0.6, 0.6, 0), 0.6, 1);
	object_prepare(o);
	check_hit(o, v3(0.1, 0.2, -10), v3(0, 0, 1), v3(0.1, 0.2, -0.6282009279),
	          v3(-0.1378775230, 0.4691310196, -0.8722991890));
	check_hit(o, v3(0.31, -0.2, -10), v3(0, 0, 1), v3(0.31, -0.2, -0.3747602058),
	          v3(0.5267193949, -0.7608196597, -0.3791043714));
	check_hit(o, v3(-5, 0.1, 0.2), v3(1, 0, 0), v3(-0.5257516593, 0.1, 0.2),
	          v3(-0.6366819082, 0.7451318642, 0.1985312384));
	object_free(o);

	/* The obsolete `component 1, 1, <0,0,0>` form is a sphere. */
	o = blob_new(nopos);
	blob_set_threshold(o, 0.5);
	blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	blob_add_sphere(o, v3(0.8, 0.3, 0), 0.8, 2);
	object_prepare(o);
	check_hit(o, v3(0.31, -0.2, -10), v3(0, 0, 1), v3(0.31, -0.2, -0.3959712348),
	          v3(0.5728053102, -0.3695518130, -0.7316594386));
	object_free(o);
}

/* POV-Ray's bounds: element spheres, radii grown by the row sums of the
 * component's transform (and of a cylinder's turn from z to its axis);
 * negative components left out. */
static void test_bounds(void **state)
{
	(void)state;
	struct object *o = blob_new(nopos);
	blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	blob_add_sphere(o, v3(1, 0, 0), 1, -0.5);
	blob_add_cylinder(o, v3(0, 1, 0), v3(0, 1, 2), 0.5, 2);
	check_box(o, v3(-1.11803401, -1, -1), v3(1.11803401, 2.11803412, 2.5));
	object_free(o);
	/* scale <1,2,1> rotate 30*z: 2 cos 30 + sin 30. */
	o = blob_new(nopos);
	int c = blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	struct xform t = xform_scale(v3(1, 2, 1));
	blob_transform_component(o, c, &t, false);
	t = xform_rotate(v3(0, 0, 30));
	blob_transform_component(o, c, &t, true);
	check_box(o, v3(-2.23205090, -2.23205090, -2.23205090), v3(2.23205090, 2.23205090, 2.23205090));
	object_free(o);
	/* rotate 30*z translate x scale <1,2,1>: the first two move the centre. */
	o = blob_new(nopos);
	c = blob_add_sphere(o, v3(0, 0, 0), 1, 1);
	t = xform_rotate(v3(0, 0, 30));
	blob_transform_component(o, c, &t, true);
	t = xform_translate(v3(1, 0, 0));
	blob_transform_component(o, c, &t, true);
	t = xform_scale(v3(1, 2, 1));
	blob_transform_component(o, c, &t, false);
	check_box(o, v3(-1, -2, -2), v3(3, 2, 2));
	object_free(o);
	/* A cylinder along <1,-2,-2>: the turn's row sum is 5/3. */
	o = blob_new(nopos);
	blob_add_cylinder(o, v3(1, 2, 3), v3(2, 0, 1), 1.5, 1);
	check_box(o, v3(-2.03553367, -2.53553367, -1.53553367), v3(5.03553391, 4.53553391, 5.53553391));
	object_free(o);
}

/* hierarchy on and off find the same crossings, normals and fields
 * (the tree only skips components far from the ray or the point). */
static void test_hierarchy(void **state)
{
	(void)state;
	struct object *o[2];
	for (int h = 0; h < 2; h++) {
		o[h] = blob_new(nopos);
		blob_set_threshold(o[h], 0.5);
		unsigned seed = 12345;
		for (int i = 0; i < 60; i++) {
			double v[7];
			for (int k = 0; k < 7; k++) {
				seed = seed * 1103515245u + 12345u;
				v[k] = (seed >> 8 & 0xffff) / 65536.0;
			}
			if (i % 3 == 0)
				blob_add_cylinder(o[h], v3(4 * v[0] - 2, 4 * v[1] - 2, 4 * v[2] - 2),
				                  v3(4 * v[3] - 2, 4 * v[4] - 2, 4 * v[5] - 2), 0.3 + 0.4 * v[6], 1);
			else
				blob_add_sphere(o[h], v3(4 * v[0] - 2, 4 * v[1] - 2, 4 * v[2] - 2), 0.3 + 0.5 * v[6],
				                i % 7 == 0 ? -0.5 : 1);
		}
		blob_set_hierarchy(o[h], h == 0);
		object_prepare(o[h]);
	}
	int hits_found = 0;
	for (int k = 0; k < 200; k++) {
		vec3 org = v3(5 * cos(k * 0.31), 3 * sin(k * 0.17), 5 * sin(k * 0.31));
		vec3 dir = v3_add(v3_neg(org), v3(sin(k), cos(k * 1.3), 0.5 * sin(k * 0.7)));
		struct hit a[16], b[16];
		struct ray r = mkray(org, dir);
		int na = o[0]->ops->all_hits(o[0], &r, 0, INFINITY, a, 16);
		int nb = o[1]->ops->all_hits(o[1], &r, 0, INFINITY, b, 16);
		assert_int_equal(na, nb);
		for (int i = 0; i < na; i++) {
			assert_near(a[i].t, b[i].t, 1e-12);
			vec3 p = v3_madd(org, dir, a[i].t);
			vec3 na_ = v3_norm(o[0]->ops->normal(o[0], p, &a[i]));
			vec3 nb_ = v3_norm(o[1]->ops->normal(o[1], p, &b[i]));
			assert_vec_near(na_, nb_.x, nb_.y, nb_.z, 1e-12);
			assert_near(blob_density(o[0], p), blob_density(o[1], p), 1e-12);
		}
		hits_found += na;
	}
	assert_true(hits_found > 100);
	object_free(o[0]);
	object_free(o[1]);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_single),
		cmocka_unit_test(test_manual),
		cmocka_unit_test(test_components),
		cmocka_unit_test(test_bounds),
		cmocka_unit_test(test_hierarchy),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_isosurface.c: unit tests for the isosurface (src/geom/isosurface.c).
 * The expected hits were measured with POV-Ray 3.7's trace() on
 * isosurface { function { x*x + y*y + (z - C)*(z - C) } threshold R*R
 * max_gradient G } in the default box, from <0, 0, -10> along +z, printed
 * as (z + 1) * 1024 (the search halves the box's 2 units down to 1/1024):
 * the far end of the first bracket the max_gradient test keeps, or a miss
 * where G is too small. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes2.h"
#include "scene/fn.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* x*x + y*y + (z - c)*(z - c) */
static struct fn *sphere_fn(double c)
{
	struct fn *f = fn_new(3);
	for (int k = 0; k < 3; k++) {
		fn_emit(f, (struct fn_instr){.op = FN_ARG, .i = k});
		if (k == 2) {
			fn_emit(f, (struct fn_instr){.op = FN_CONST, .k = c});
			fn_emit(f, (struct fn_instr){.op = FN_SUB});
		}
		fn_emit(f, (struct fn_instr){.op = FN_ARG, .i = k});
		if (k == 2) {
			fn_emit(f, (struct fn_instr){.op = FN_CONST, .k = c});
			fn_emit(f, (struct fn_instr){.op = FN_SUB});
		}
		fn_emit(f, (struct fn_instr){.op = FN_MUL});
		if (k)
			fn_emit(f, (struct fn_instr){.op = FN_ADD});
	}
	f->depth = 4;
	return f;
}

static void test_search(void **state)
{
	(void)state;
	/* Rows: C, G as the number of steps of 0.1 after 0.2 (the values the
	 * scene's #for loops made, sums of 0.1s, which matter at ties);
	 * columns R = 0.1 .. 0.9, summed the same way; -1 a miss. */
	static const struct { double c; int g; double want[9]; } rows[] = {
		{-0.3, 6, {-1, -1, -1, -1, -1, 129, 1, 0, 0}},
		{-0.3, 7, {-1, -1, -1, -1, 205, 103, 1, 0, 0}},
		{0, 4, {-1, -1, -1, -1, -1, -1, 321, 257, 129}},
		{0, 7, {-1, -1, -1, 615, 513, 513, 308, 257, 129}},
		{0.3, 3, {-1, -1, -1, -1, -1, -1, -1, 1025, 513}},
		{0.3, 7, {-1, -1, -1, -1, 1025, 1025, 641, 513, 513}},
	};
	for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
		struct fn *f = sphere_fn(rows[i].c);
		double g = 0.2, R = 0.1;
		for (int k = 0; k < rows[i].g; k++)
			g += 0.1;
		for (int k = 0; k < 9; k++, R += 0.1) {
			struct object *o = isosurface_new(f, nopos);
			isosurface_set_threshold(o, R * R);
			isosurface_set_max_gradient(o, g);
			struct ray r = mkray(v3(0, 0, -10), v3(0, 0, 1));
			struct hit h;
			bool hit = object_intersect(o, &r, 0, INFINITY, &h);
			double got = hit ? (-10 + h.t + 1) * 1024 : -1;
			if (fabs(got - rows[i].want[k]) > 1e-6)
				fail_msg("C %g G %g R %g: got %g, POV-Ray %g", rows[i].c, g, R, got, rows[i].want[k]);
			object_free(o);
		}
		fn_unref(f);
	}
}

/* Normals: forward differences with the accuracy as step (POV-Ray's
 * normal at the hit of r*r = 0.5: 0.000709, 0.000709, -0.999999). */
static void test_normal_and_inside(void **state)
{
	(void)state;
	struct fn *f = sphere_fn(0);
	struct object *o = isosurface_new(f, nopos);
	fn_unref(f);
	isosurface_set_threshold(o, 0.5);
	struct hit h = must_hit(o, v3(0, 0, -10), v3(0, 0, 1), 0);
	assert_near(-10 + h.t, -0.70605469, 5e-9);
	vec3 n = v3_norm(o->ops->normal(o, v3(0, 0, -10 + h.t), &h));
	assert_vec_near(n, 0.000709, 0.000709, -0.999999, 2e-6);
	assert_true(object_inside(o, v3(0, 0, 0)));
	assert_false(object_inside(o, v3(0.9, 0, 0)));
	/* Outside the container nothing is inside. */
	isosurface_set_threshold(o, 100);
	assert_false(object_inside(o, v3(1.5, 0, 0)));
	/* A ray entering the container inside the solid hits the container. */
	h = must_hit(o, v3(0, 0, -10), v3(0, 0, 1), 0);
	assert_near(h.t, 9, 1e-12);
	assert_vec_near(v3_norm(o->ops->normal(o, v3(0, 0, -1), &h)), 0, 0, -1, 1e-12);
	/* open: no container walls. */
	isosurface_set_open(o, true);
	assert_false(hits(o, v3(0, 0, -10), v3(0, 0, 1), 0, INFINITY));
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, -1, -1, -1, 0);
	isosurface_set_sphere(o, v3(1, 0, 0), 2);
	b = o->ops->bounds(o);
	assert_vec_near(b.lo, -1, -2, -2, 0);
	assert_vec_near(b.hi, 3, 2, 2, 0);
	double found, given;
	assert_true(isosurface_gradient_report(o, &found, &given));
	assert_near(given, 1.1, 0);
	assert_true(found > 0);
	object_free(o);
}

/* POV-Ray skips crossings near the start of a ray that begins in the
 * container: function { -z }, accuracy 0.001, from <0.1, 0.1, -D*0.00025>
 * along +z misses the surface for D <= 17 (the container's far wall is
 * hit) and finds it for D >= 18. */
static void test_start_in_container(void **state)
{
	(void)state;
	struct fn *f = fn_new(3);
	fn_emit(f, (struct fn_instr){.op = FN_ARG, .i = 2});
	fn_emit(f, (struct fn_instr){.op = FN_NEG});
	f->depth = 1;
	struct object *o = isosurface_new(f, nopos);
	fn_unref(f);
	for (int d = 1; d <= 40; d++) {
		double z0 = -d * 0.00025;
		struct hit h = must_hit(o, v3(0.1, 0.1, z0), v3(0, 0, 1), 0);
		bool far = fabs(z0 + h.t - 1) < 1e-12;
		if (far != (d <= 17))
			fail_msg("D %d: hit at z %g", d, z0 + h.t);
	}
	object_free(o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_search),
		cmocka_unit_test(test_normal_and_inside),
		cmocka_unit_test(test_start_in_container),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

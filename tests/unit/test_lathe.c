/* test_lathe.c: unit tests for the lathe (src/geom/lathe.c), hit through
 * the shape-independent layer. The expected points, normals, inside
 * answers and bounds were measured with POV-Ray 3.7's trace(), inside(),
 * min_extent() and max_extent() on the same lathes (scenes like
 *   #declare H = trace(L, <0, 0.5, -10>, z, N);
 *   #debug concat(vstr(3, H, ",", 0, 8), " ", vstr(3, N, ",", 0, 6), "\n")
 * run with povray -D -F +W8 +H8), printed to 8 and 6 digits. lucent's
 * normals face the ray; POV-Ray's raw sign is checked on the op. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes2.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

static struct object *make(enum lathe_spline kind, const double (*pts)[2], int n)
{
	struct object *o = lathe_new(kind, pts, n, nopos);
	assert_string_equal(o->ops->name, "lathe");
	object_prepare(o);
	return o;
}

/* The z of the hit of the ray from <0, y, -10> along +z, and the raw normal. */
static double front_z(const struct object *o, double y, vec3 *raw)
{
	vec3 org = v3(0, y, -10), dir = v3(0, 0, 1);
	struct hit h = must_hit(o, org, dir, 0);
	vec3 p = v3_madd(org, dir, h.t);
	if (raw)
		*raw = v3_norm(o->ops->normal(o, p, &h));
	return p.z;
}

/* The manual's thick cylinder, then drawn the other way round. */
static void test_linear(void **state)
{
	(void)state;
	static const double pts[][2] = {{2, 0}, {3, 0}, {3, 5}, {2, 5}, {2, 0}};
	struct object *o = make(LATHE_LINEAR_SPLINE, pts, 5);
	vec3 n;
	assert_near(front_z(o, 2.5, &n), -3, 1e-12);
	assert_vec_near(n, 0, 0, -1, 1e-9);
	/* From inside the hole. */
	struct hit h = must_hit(o, v3(0, 2.5, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 2, 1e-12);
	/* Top and bottom. */
	h = must_hit(o, v3(2.5, 10, 0), v3(0, -1, 0), 0);
	assert_near(10 - h.t, 5, 1e-12);
	assert_vec_near(v3_norm(o->ops->normal(o, v3(2.5, 5, 0), &h)), 0, 1, 0, 1e-9);
	/* A slanted ray. */
	h = must_hit(o, v3(1, 1, -10), v3(0.1, 0.2, 1), 0);
	vec3 p = v3_madd(v3(1, 1, -10), v3(0.1, 0.2, 1), h.t);
	assert_vec_near(p, 1.75682150, 2.51364300, -2.43178498, 5e-9);
	assert_vec_near(v3_norm(o->ops->normal(o, p, &h)), 0.585607, 0, -0.810595, 2e-6);
	assert_true(object_inside(o, v3(2.5, 1, 0)));
	assert_false(object_inside(o, v3(1, 1, 0)));
	assert_true(object_inside(o, v3(0, 1, 2.5)));
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, -3, 0, -3, 1e-12);
	assert_vec_near(b.hi, 3, 5, 3, 1e-12);
	object_free(o);
	/* Reversed: the raw normals turn inward. */
	static const double rev[][2] = {{2, 0}, {2, 5}, {3, 5}, {3, 0}, {2, 0}};
	o = make(LATHE_LINEAR_SPLINE, rev, 5);
	front_z(o, 2.5, &n);
	assert_vec_near(n, 0, 0, 1, 1e-9);
	object_free(o);
}

static void test_curves(void **state)
{
	(void)state;
	static const double q[][2] = {{0, -1}, {1, 0}, {2, 1}, {1, 2}, {0, 3}};
	struct object *o = make(LATHE_QUADRATIC_SPLINE, q, 5);
	vec3 n;
	assert_near(front_z(o, 0.5, &n), -1.5, 1e-9);
	assert_vec_near(n, 0, -0.707107, -0.707107, 2e-6);
	assert_near(front_z(o, 1.5, &n), -1.75, 1e-9);
	assert_vec_near(n, 0, 0.707107, -0.707107, 2e-6);
	assert_false(hits(o, v3(0, -0.5, -10), v3(0, 0, 1), 0, INFINITY));
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, -2, 0, -2, 1e-12);
	assert_vec_near(b.hi, 2, 3, 2, 1e-12);
	object_free(o);

	static const double c[][2] = {{0, -1}, {1, 0}, {2, 1}, {1, 2}, {0.5, 3}, {1, 4}};
	o = make(LATHE_CUBIC_SPLINE, c, 6);
	lathe_set_sturm(o, true);
	assert_near(front_z(o, 0.5, &n), -1.625, 1e-9);
	assert_vec_near(n, 0, -0.780869, -0.624695, 2e-6);
	assert_near(front_z(o, 1.5, &n), -1.59375, 1e-9);
	assert_vec_near(n, 0, 0.795432, -0.606043, 2e-6);
	assert_near(front_z(o, 2.5, &n), -0.65625, 1e-9);
	assert_vec_near(n, 0, 0.490261, -0.871576, 2e-6);
	object_free(o);
	/* A cubic that overshoots its points: the bounds are the curve's. */
	static const double c2[][2] = {{0, 0}, {1, 0}, {2, 1}, {0.5, 2}, {1, 3}, {0, 4}};
	o = make(LATHE_CUBIC_SPLINE, c2, 6);
	b = o->ops->bounds(o);
	assert_near(b.hi.x, 2.00641584, 2e-7); /* POV-Ray's bounds are single precision */
	assert_near(b.hi.y, 3, 1e-12);
	object_free(o);

	static const double z[][2] = {{1, 0}, {2, 1}, {2, 2}, {1, 3}, {1, 3}, {0.5, 3.5}, {0.5, 4}, {1, 5}};
	o = make(LATHE_BEZIER_SPLINE, z, 8);
	assert_near(front_z(o, 0.5, &n), -1.41666667, 5e-9);
	assert_vec_near(n, 0, -0.554700, -0.832050, 2e-6);
	assert_near(front_z(o, 1.5, &n), -1.75, 1e-9);
	assert_near(front_z(o, 3.5, &n), -0.67242707, 5e-9);
	assert_vec_near(n, 0, 0.306662, -0.951818, 2e-6);
	assert_false(hits(o, v3(0.2, 10, 0.1), v3(0, -1, 0), 0, INFINITY));
	object_free(o);
	/* Bezier bounds are the control points'. */
	static const double z2[][2] = {{1, 0}, {1, -1}, {0, 4}, {1, 3}};
	o = make(LATHE_BEZIER_SPLINE, z2, 4);
	b = o->ops->bounds(o);
	assert_vec_near(b.lo, -1, -1, -1, 1e-12);
	assert_vec_near(b.hi, 1, 4, 1, 1e-12);
	object_free(o);
}

/* all_hits lists the crossings in order; a horizontal ray (d.y = 0) too. */
static void test_all_hits(void **state)
{
	(void)state;
	static const double pts[][2] = {{2, 0}, {3, 0}, {3, 5}, {2, 5}, {2, 0}};
	struct object *o = make(LATHE_LINEAR_SPLINE, pts, 5);
	struct ray r = mkray(v3(0, 2.5, -10), v3(0, 0, 1));
	struct hit out[8];
	int n = o->ops->all_hits(o, &r, 0, INFINITY, out, 8);
	assert_int_equal(n, 4);
	double want[] = {7, 8, 12, 13};
	for (int i = 0; i < 4; i++)
		assert_near(out[i].t, want[i], 1e-12);
	object_free(o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_linear),
		cmocka_unit_test(test_curves),
		cmocka_unit_test(test_all_hits),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_sweep.c: unit tests for sphere_sweep (src/geom/sweep.c). The
 * expected values were measured with POV-Ray 3.7's trace(), inside(),
 * min_extent() and max_extent() on the same sweeps, e.g.
 *   #declare L = sphere_sweep { linear_spline 3, <0,0,0>, 0.5, <2,1,0>, 0.25, <3,-1,1>, 0.75 }
 *   #declare N = <0,0,0>;
 *   #declare P = trace(L, <1,0.5,-5>, z, N);
 *   #write(F, concat(vstr(3,P,",",0,12), " ", vstr(3,N,",",0,12), "\n"))
 * printed to 12 digits (bounds: 8; POV-Ray keeps them in single
 * precision). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/sweep.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* The five spheres the tests sweep (the linear sweep uses the middle three). */
static const vec3 centers[5] = {{-1, 0, 0}, {0, 0, 0}, {2, 1, 0}, {3, -1, 1}, {4, 0, 0}};
static const double radii[5] = {0.3, 0.5, 0.25, 0.75, 0.4};

static struct object *make(enum sweep_spline kind)
{
	struct object *o = kind == SWEEP_LINEAR ? sweep_new(kind, centers + 1, radii + 1, 3, nopos)
	                                        : sweep_new(kind, centers, radii, 5, nopos);
	object_prepare(o);
	return o;
}

/* linear_spline: the spheres joined by their tangent cones. */
static void test_linear(void **state)
{
	(void)state;
	struct object *o = make(SWEEP_LINEAR);
	check_box(o, v3(-0.5, -1.75, -0.5), v3(3.75, 1.25, 1.75));
	/* On the cone between the first two spheres, entering and leaving. */
	check_hit(o, v3(1, 0.5, -5), v3(0, 0, 1), v3(1, 0.5, -0.377365954070),
	          v3(0.1, 0.05, -0.993730345718));
	check_hit(o, v3(1, 0.5, 0), v3(0, 0, 1), v3(1, 0.5, 0.377365954070), v3(0.1, 0.05, 0.993730345718));
	/* On the first sphere's cap. */
	check_hit(o, v3(-3, 0.1, 0.05), v3(1, 0, 0), v3(-0.487339717240, 0.1, 0.05),
	          v3(-0.974679434481, 0.2, 0.1));
	assert_false(hits(o, v3(1, 5, -5), v3(0.1, -1, 1), 0, INFINITY));
	assert_true(object_inside(o, v3(1, 0.5, 0)));
	assert_true(object_inside(o, v3(1, 0.8, 0)));
	assert_false(object_inside(o, v3(1, 2, 0)));
	object_free(o);
}

/* b_spline: the uniform cubic B-spline of the centres and radii; bounded
 * by the given spheres. */
static void test_b_spline(void **state)
{
	(void)state;
	struct object *o = make(SWEEP_B_SPLINE);
	check_box(o, v3(-1.3, -1.75, -0.5), v3(4.4, 1.25, 1.75));
	check_hit(o, v3(1, 0.5, -5), v3(0, 0, 1), v3(1, 0.5, -0.359715652206),
	          v3(0.084573403598, 0.133356264835, -0.987453009532));
	check_hit(o, v3(2, 0, -5), v3(0, 0.1, 1), v3(2, 0.482224141338, -0.177758586616),
	          v3(0.260588135034, 0.020976133438, -0.965222163911));
	/* From inside, leaving through the first piece's end sphere. */
	check_hit(o, v3(0, 0, 0), v3(0, 0, 1), v3(0, 0, 0.353651586232),
	          v3(-0.392156862745, -0.392156862745, 0.832121379370));
	assert_false(hits(o, v3(1, 5, -5), v3(0.1, -1, 1), 0, INFINITY));
	object_free(o);
}

/* cubic_spline: Catmull-Rom through the second to the fourth sphere;
 * POV-Ray's box is the given spheres with their radii doubled. */
static void test_cubic(void **state)
{
	(void)state;
	struct object *o = make(SWEEP_CUBIC);
	check_box(o, v3(-1.6, -2.5, -1), v3(4.8, 1.5, 2.5));
	check_hit(o, v3(1, 0.5, -5), v3(0, 0, 1), v3(1, 0.5, -0.412668948123),
	          v3(0.238328489446, -0.175168933084, -0.955256706860));
	check_hit(o, v3(2, 0, -5), v3(0, 0.1, 1), v3(2, 0.519863863755, 0.198638637545),
	          v3(-0.954975853609, -0.270444747204, -0.121986711297));
	check_hit(o, v3(1, 0.5, 0), v3(0, 0, 1), v3(1, 0.5, 0.300293082199),
	          v3(0.319947980165, -0.114199349676, 0.940527404450));
	assert_true(object_inside(o, v3(1, 0.5, 0)));
	assert_false(object_inside(o, v3(3.5, -0.5, 0.5)));
	assert_false(object_inside(o, v3(-1, 0, 0))); /* the first sphere only steers the curve */
	object_free(o);
}

/* all_hits: the entry and exit of each stretch of the ray inside, the
 * spans of overlapping pieces merged (CSG needs no crossing inside the
 * solid). */
static void test_all_hits(void **state)
{
	(void)state;
	struct object *o = make(SWEEP_LINEAR);
	struct ray r = mkray(v3(1, 0.5, -5), v3(0, 0, 1));
	struct hit h[8];
	int n = o->ops->all_hits(o, &r, 0, INFINITY, h, 8);
	assert_int_equal(n, 2);
	assert_near(h[0].t, 5 - 0.377365954070, 1e-9);
	assert_near(h[1].t, 5 + 0.377365954070, 1e-9);
	/* Along the axis through every sphere: one stretch. */
	r = mkray(v3(-5, 0, 0), v3(1, 0, 0));
	n = o->ops->all_hits(o, &r, 0, INFINITY, h, 8);
	assert_int_equal(n % 2, 0);
	for (int i = 1; i < n; i++)
		assert_true(h[i].t > h[i - 1].t);
	object_free(o);
}

/* tolerance: crossings nearer than it along the unit direction are not
 * reported (POV-Ray: tolerance 0.5, a ray from 0.3 below the surface
 * misses, one from 0.7 below hits, whatever the direction's length). */
static void test_tolerance(void **state)
{
	(void)state;
	const vec3 c[2] = {{0, 0, 0}, {2, 0, 0}};
	const double r[2] = {1, 1};
	struct object *o = sweep_new(SWEEP_LINEAR, c, r, 2, nopos);
	sweep_set_tolerance(o, 0.5);
	object_prepare(o);
	check_hit(o, v3(0.5, 0, 0), v3(0, 0, 1), v3(0.5, 0, 1), v3(0, 0, 1));
	assert_false(hits(o, v3(0.5, 0, 0.7), v3(0, 0, 1), 0, INFINITY));
	check_hit(o, v3(0.5, 0, 0.3), v3(0, 0, 2), v3(0.5, 0, 1), v3(0, 0, 1));
	object_free(o);
}

/* Negative radii, as POV-Ray takes them: a linear piece has no spheres
 * where its radius is below 0; a curved one keeps them, and its normal
 * there, (p - C) / R, points inward. inside() counts them all. (POV-Ray
 * trace() values printed to 9 digits.) */
static void test_negative_radius(void **state)
{
	(void)state;
	const vec3 c[4] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
	const double neg[2] = {-0.5, -0.5}, mixed[2] = {-0.5, 0.5}, b[4] = {-0.5, -0.5, 0.5, 0.5};
	const vec3 c2[2] = {{0, 0, 0}, {2, 0, 0}};
	struct object *o = sweep_new(SWEEP_LINEAR, c2, neg, 2, nopos);
	object_prepare(o);
	assert_false(hits(o, v3(1, 0.1, -5), v3(0, 0, 1), 0, INFINITY));
	assert_true(object_inside(o, v3(1, 0, 0)));
	object_free(o);
	o = sweep_new(SWEEP_LINEAR, c2, mixed, 2, nopos);
	object_prepare(o);
	assert_false(hits(o, v3(0.2, 0.1, -5), v3(0, 0, 1), 0, INFINITY));
	check_hit(o, v3(1.8, 0.1, -5), v3(0, 0, 1), v3(1.8, 0.1, -0.447213595), v3(-0.4, 0.2, -0.894427191));
	object_free(o);
	o = sweep_new(SWEEP_B_SPLINE, c, b, 4, nopos);
	object_prepare(o);
	struct hit h = must_hit(o, v3(1.2, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 5 - 0.268623772, 1e-9);
	vec3 n = hit_normal(o, v3(1.2, 0, -5), v3(0, 0, 1), &h);
	assert_vec_near(n, -0.530763522, 0, 0.847519960, 1e-9);
	object_free(o);
}

/* Copies own their pieces. */
static void test_copy(void **state)
{
	(void)state;
	struct object *o = make(SWEEP_CUBIC);
	struct object *c = object_copy(o);
	object_free(o);
	object_prepare(c);
	check_hit(c, v3(1, 0.5, -5), v3(0, 0, 1), v3(1, 0.5, -0.412668948123),
	          v3(0.238328489446, -0.175168933084, -0.955256706860));
	object_free(c);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_linear),    cmocka_unit_test(test_b_spline), cmocka_unit_test(test_cubic),
		cmocka_unit_test(test_all_hits),  cmocka_unit_test(test_tolerance), cmocka_unit_test(test_copy),
		cmocka_unit_test(test_negative_radius),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

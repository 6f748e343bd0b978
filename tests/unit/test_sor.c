/* test_sor.c: unit tests for the surface of revolution (src/geom/sor.c) and
 * the polygon (src/geom/polygon.c). The expected values were measured
 * with POV-Ray 3.7's trace(), inside(), min_extent() and max_extent() on
 * the same objects (see test_lathe.c for the scenes' form), printed to 8
 * and 6 digits. */
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

/* The hit point of the ray, and the raw normal there. */
static vec3 hit_at(const struct object *o, vec3 org, vec3 dir, vec3 *raw)
{
	struct hit h = must_hit(o, org, dir, 0);
	vec3 p = v3_madd(org, dir, h.t);
	if (raw)
		*raw = v3_norm(o->ops->normal(o, p, &h));
	return p;
}

/* The manual's vase, closed. */
static void test_vase(void **state)
{
	(void)state;
	static const double pts[][2] = {{0, 0}, {0.118143, 0}, {0.620253, 0.540084}, {0.210970, 0.827004},
	                                {0.194093, 0.962025}, {0.286920, 1}, {0.468354, 1.033755}};
	assert_int_equal(sor_check(pts, 7), -1);
	struct object *o = sor_new(pts, 7, nopos);
	object_prepare(o);
	vec3 n, p;
	p = hit_at(o, v3(0, 0.3, -10), v3(0, 0, 1), &n);
	assert_near(p.z, -0.48562313, 5e-9);
	assert_vec_near(n, 0, -0.684066, -0.729420, 2e-6);
	p = hit_at(o, v3(0, 0.6, -10), v3(0, 0, 1), &n);
	assert_near(p.z, -0.59652650, 5e-9);
	assert_vec_near(n, 0, 0.646878, -0.762594, 2e-6);
	p = hit_at(o, v3(0, 0.9, -10), v3(0, 0, 1), &n);
	assert_near(p.z, -0.17612634, 5e-9);
	assert_vec_near(n, 0, -0.032515, -0.999471, 2e-6);
	/* From inside: the raw normal still points out. */
	p = hit_at(o, v3(0, 0.6, 0), v3(0, 0, 1), &n);
	assert_near(p.z, 0.59652650, 5e-9);
	assert_vec_near(n, 0, 0.646878, 0.762594, 2e-6);
	/* The caps. */
	p = hit_at(o, v3(0.1, 10, 0), v3(0, -1, 0), &n);
	assert_near(p.y, 1, 1e-12);
	assert_vec_near(n, 0, 1, 0, 1e-12);
	p = hit_at(o, v3(0.1, -10, 0), v3(0, 1, 0), &n);
	assert_near(p.y, 0, 1e-12);
	assert_vec_near(n, 0, -1, 0, 1e-12);
	p = hit_at(o, v3(0.5, -10, 0), v3(0, 1, 0), &n);
	assert_near(p.y, 0.31568407, 5e-9);
	assert_vec_near(n, 0.745039, -0.667021, 0, 2e-6);
	p = hit_at(o, v3(0.3, 0.5, 0), v3(0, -1, 0), &n);
	assert_near(p.y, 0.13633568, 5e-9);
	assert_true(object_inside(o, v3(0.1, 0.3, 0)));
	assert_true(object_inside(o, v3(0.55, 0.5, 0)));
	assert_false(object_inside(o, v3(0, 1.1, 0)));
	assert_false(object_inside(o, v3(0, -0.1, 0)));
	/* POV-Ray keeps bounds in single precision: 0.62058592. */
	struct aabb b = o->ops->bounds(o);
	assert_near(b.hi.x, 0.62058592, 5e-8);
	assert_near(b.lo.y, 0, 1e-12);
	assert_near(b.hi.y, 1, 1e-12);
	object_free(o);
}

static void test_segment_and_open(void **state)
{
	(void)state;
	static const double pts[][2] = {{1, -1}, {1, 0}, {2, 1}, {2, 2}};
	struct object *o = sor_new(pts, 4, nopos);
	object_prepare(o);
	vec3 n, p = hit_at(o, v3(0, 0.5, -10), v3(0, 0, 1), &n);
	assert_near(p.z, -1.54110350, 5e-9);
	assert_vec_near(n, 0, -0.772539, -0.634967, 2e-6);
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, -2, 0, -2, 1e-12);
	assert_vec_near(b.hi, 2, 1, 2, 1e-12);
	sor_set_open(o, true);
	assert_false(hits(o, v3(0.5, 10, 0), v3(0, -1, 0), 0, INFINITY));
	p = hit_at(o, v3(0, 0.5, 0), v3(0, 0, 1), &n);
	assert_near(p.z, 1.54110350, 5e-9);
	assert_vec_near(n, 0, -0.772539, 0.634967, 2e-6);
	object_free(o);
	/* The curve's largest radius bounds it (1.26197958). */
	static const double q[][2] = {{0, 1}, {1, 0}, {1, 2}, {1, 3}};
	o = sor_new(q, 4, nopos);
	assert_near(o->ops->bounds(o).hi.x, 1.26197958, 2e-7); /* single precision */
	object_free(o);
	static const double bad[][2] = {{0, 0}, {1, 1}, {1, 1}, {1, 2}};
	assert_int_equal(sor_check(bad, 4), 2);
}

/* The manual's letter P: a hole from the second sub-polygon. */
static void test_polygon(void **state)
{
	(void)state;
	static const vec3 pts[] = {{0, 0, 0}, {0, 6, 0}, {4, 6, 0}, {4, 3, 0}, {1, 3, 0}, {1, 0, 0}, {0, 0, 0},
	                           {1, 4, 0}, {1, 5, 0}, {3, 5, 0}, {3, 4, 0}, {1, 4, 0}};
	bool closed, nonplanar;
	struct object *o = polygon_new(pts, 12, nopos, &closed, &nonplanar);
	assert_false(closed);
	assert_false(nonplanar);
	vec3 n;
	hit_at(o, v3(0.5, 0.5, -10), v3(0, 0, 1), &n);
	assert_vec_near(n, 0, 0, -1, 1e-12);
	hit_at(o, v3(0.5, 0.5, 10), v3(0, 0, -1), &n);
	assert_vec_near(n, 0, 0, -1, 1e-12);
	assert_false(hits(o, v3(2, 4.5, -10), v3(0, 0, 1), 0, INFINITY));
	vec3 p = hit_at(o, v3(2, 3.5, -10), v3(0, 0, 1), NULL);
	assert_vec_near(p, 2, 3.5, 0, 1e-12);
	assert_false(object_inside(o, v3(0.5, 0.5, 0)));
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, 0, 0, -0.001, 1e-12);
	assert_vec_near(b.hi, 4, 6, 0.001, 1e-12);
	object_free(o);
	/* Not closed: closed for us; slanted normal (P1 - P0) x (P2 - P0). */
	static const vec3 s[] = {{0, 0, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
	o = polygon_new(s, 4, nopos, &closed, &nonplanar);
	assert_true(closed);
	p = hit_at(o, v3(0.5, 0.5, -10), v3(0, 0, 1), &n);
	assert_vec_near(p, 0.5, 0.5, 0.5, 1e-12);
	assert_vec_near(n, -0.707107, 0, 0.707107, 2e-6);
	object_free(o);
	/* A corner 1e-9 off the plane hides it; 1e-10 does not. */
	static const vec3 off[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-9}, {0, 1, 0}, {0, 0, 0}};
	o = polygon_new(off, 5, nopos, &closed, &nonplanar);
	assert_true(nonplanar);
	assert_false(hits(o, v3(0.5, 0.5, -1), v3(0, 0, 1), 0, INFINITY));
	object_free(o);
	static const vec3 on[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-10}, {0, 1, 0}, {0, 0, 0}};
	o = polygon_new(on, 5, nopos, &closed, &nonplanar);
	assert_false(nonplanar);
	assert_true(hits(o, v3(0.5, 0.5, -1), v3(0, 0, 1), 0, INFINITY));
	object_free(o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_vase),
		cmocka_unit_test(test_segment_and_open),
		cmocka_unit_test(test_polygon),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

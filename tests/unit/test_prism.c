/* test_prism.c: unit tests for the prism (src/geom/prism.c), hit through
 * the shape-independent layer (src/scene/object.h). The expected points,
 * normals, inside answers and bounds were measured with POV-Ray 3.7's
 * trace(), inside(), min_extent() and max_extent() on the same prisms
 * (scenes like
 *   #declare H = trace(P, <X, 0.5, -5>, z, N);
 *   #debug concat(vstr(3, H, ",", 0, 8), " ", vstr(3, N, ",", 0, 6), "\n")
 * run with povray -D -F +W8 +H8), printed to 8 and 6 digits. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

static struct object *make(enum prism_spline kind, bool conic, double h1, double h2, const double (*pts)[2], int n,
                           struct prism_report *rep)
{
	struct object *o = prism_new(kind, conic, h1, h2, pts, n, nopos, rep);
	assert_string_equal(o->ops->name, "prism");
	object_prepare(o);
	return o;
}

/* The z of the hit of the ray from <x, y, zfrom> along +z or -z. */
static double hit_z(const struct object *o, double x, double y, double zfrom, vec3 *n)
{
	vec3 org = v3(x, y, zfrom), dir = v3(0, 0, zfrom < 0 ? 1 : -1);
	struct hit h = must_hit(o, org, dir, 0);
	if (n)
		*n = hit_normal(o, org, dir, &h);
	return org.z + h.t * dir.z;
}

/* The normal POV-Ray reports, up to the sign (lucent's trace() and
 * renderer turn it to face the ray; the sign is checked separately). */
static void assert_normal_axis(vec3 n, double x, double y, double z)
{
	double s = v3_dot(n, v3(x, y, z)) < 0 ? -1 : 1;
	assert_vec_near(v3_scale(n, s), x, y, z, 2e-6);
}

/* ---- the curves: POV-Ray's points to 8 digits ---- */

static void test_quadratic(void **state)
{
	(void)state;
	static const double pts[][2] = {{0, -1}, {0, 0}, {1, 0}, {1, 1}, {0, 0}};
	struct object *o = make(PRISM_QUADRATIC_SPLINE, false, 0, 1, pts, 5, NULL);
	static const struct { double x, front, back; } want[] = {
		{0.05, 0.04160798, 0.06628783}, {0.35, 0.12467943, 0.44498996}, {0.65, 0.09498996, 0.77467943},
		{0.95, 0.01628783, 0.99160798},
	};
	for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
		assert_near(hit_z(o, want[i].x, 0.5, -5, NULL), want[i].front, 5e-9);
		assert_near(hit_z(o, want[i].x, 0.5, 5, NULL), want[i].back, 5e-9);
	}
	vec3 n;
	hit_z(o, 0.05, 0.5, -5, &n);
	assert_vec_near(n, 0.568097, 0, -0.822961, 2e-6);
	hit_z(o, 0.05, 0.5, 5, &n);
	assert_vec_near(n, -0.796652, 0, 0.604438, 2e-6);
	/* Bounds: the curve's extent (x reaches 1.125 between <1,0> and <1,1>). */
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.lo, 0, 0, 0, 1e-12);
	assert_vec_near(b.hi, 1.125, 1, 1, 1e-12);
	object_free(o);
}

static void test_cubic_and_bezier(void **state)
{
	(void)state;
	static const double cp[][2] = {{0, -1}, {0, 0}, {1, 0}, {1, 1}, {0, 0}, {0.5, 0.3}};
	static const double bp[][2] = {{0, 0}, {0.5, -0.5}, {1, -0.2}, {1, 0}, {1, 0}, {1.2, 0.5}, {0.3, 1.1}, {0, 0}};
	struct object *c = make(PRISM_CUBIC_SPLINE, false, 0, 1, cp, 6, NULL);
	struct object *b = make(PRISM_BEZIER_SPLINE, false, 0, 1, bp, 8, NULL);
	static const struct { double x, cf, cb, bf, bb; } want[] = {
		{0.05, 0.03126248, 0.06408908, -0.04738327, 0.15434267},
		{0.35, 0.02856750, 0.41356866, -0.23309391, 0.56028051},
		{0.50, 0.00000000, 0.57720200, -0.26916927, 0.61508381},
		{0.80, -0.04705267, 0.87325312, -0.22691839, 0.54691218},
		{0.95, -0.03126248, 0.98417458, -0.11779251, 0.39894981},
	};
	for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
		assert_near(hit_z(c, want[i].x, 0.5, -5, NULL), want[i].cf, 5e-9);
		assert_near(hit_z(c, want[i].x, 0.5, 5, NULL), want[i].cb, 5e-9);
		assert_near(hit_z(b, want[i].x, 0.5, -5, NULL), want[i].bf, 5e-9);
		assert_near(hit_z(b, want[i].x, 0.5, 5, NULL), want[i].bb, 5e-9);
	}
	vec3 n;
	hit_z(c, 0.05, 0.5, -5, &n);
	assert_vec_near(n, 0.356246, 0, -0.934392, 2e-6);
	/* A Bezier prism's raw normal points the other way round the curve. */
	hit_z(b, 0.05, 0.5, -5, &n);
	assert_vec_near(n, 0.667438, 0, 0.744666, 2e-6);
	/* Bounds: the cubic's curve extent; a Bezier piece's control points. */
	struct aabb bb = c->ops->bounds(c);
	assert_near(bb.lo.z, -0.048113, 5e-7);
	assert_near(bb.hi.x, 1.125, 1e-12);
	bb = b->ops->bounds(b);
	assert_vec_near(bb.lo, 0, 0, -0.5, 0);
	assert_vec_near(bb.hi, 1.2, 1, 1.1, 0);
	object_free(c);
	object_free(b);
}

/* ---- sweeps, caps, inside ---- */

static void test_linear_caps_and_orientation(void **state)
{
	(void)state;
	static const double ccw[][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}};
	static const double cw[][2] = {{0, 0}, {0, 1}, {1, 0}, {0, 0}};
	struct object *a = make(PRISM_LINEAR_SPLINE, false, 0, 1, ccw, 4, NULL);
	struct object *b = make(PRISM_LINEAR_SPLINE, false, 0, 1, cw, 4, NULL);
	/* POV-Ray: <0,0,-1> on the counter-clockwise one, <0,0,1> on the clockwise one. */
	vec3 n;
	assert_near(hit_z(a, 0.25, 0.5, -5, &n), 0, 0);
	assert_vec_near(n, 0, 0, -1, 0);
	assert_near(hit_z(b, 0.25, 0.5, -5, &n), 0, 0);
	assert_vec_near(n, 0, 0, 1, 0);
	/* Both caps give +y. */
	vec3 top = v3(0.25, 5, 0.25), down = v3(0, -1, 0);
	struct hit h = must_hit(a, top, down, 0);
	assert_near(h.t, 4, 0);
	assert_vec_near(hit_normal(a, top, down, &h), 0, 1, 0, 0);
	h = must_hit(a, v3(0.25, -5, 0.25), v3(0, 1, 0), 0);
	assert_near(h.t, 5, 0);
	assert_vec_near(hit_normal(a, v3(0.25, -5, 0.25), v3(0, 1, 0), &h), 0, 1, 0, 0);
	/* Outside the triangle, the vertical ray misses. */
	assert_false(hits(a, v3(0.6, 5, 0.6), down, 0, INFINITY));
	/* Open: no caps, the same inside. */
	prism_set_open(a, true);
	assert_false(hits(a, top, down, 0, INFINITY));
	assert_true(object_inside(a, v3(0.25, 0.5, 0.25)));
	assert_false(object_inside(a, v3(0.25, 1.5, 0.25)));
	object_free(a);
	object_free(b);
}

static void test_conic(void **state)
{
	(void)state;
	static const double sq[][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}, {1, 1}};
	struct object *c = make(PRISM_LINEAR_SPLINE, true, 0.2, 1, sq, 5, NULL);
	vec3 n;
	/* POV-Ray: <0,0.5,-0.5>, normal <0,-0.707107,-0.707107>. */
	assert_near(hit_z(c, 0, 0.5, -5, &n), -0.5, 1e-12);
	assert_normal_axis(n, 0, -0.707107, -0.707107);
	/* <-5,0.75,0.1> + t x: <-0.75,0.75,0.1>, normal <-0.707107,-0.707107,0>. */
	vec3 org = v3(-5, 0.75, 0.1), dx = v3(1, 0, 0);
	struct hit h = must_hit(c, org, dx, 0);
	assert_near(h.t, 4.25, 1e-12);
	assert_normal_axis(hit_normal(c, org, dx, &h), -0.707107, -0.707107, 0);
	/* The bottom cap is the square scaled by 0.2. */
	h = must_hit(c, v3(0.1, -5, 0.1), v3(0, 1, 0), 0);
	assert_near(h.t, 5.2, 1e-12);
	/* A diagonal ray: POV-Ray's <-0.5,0.5,-0.25>. */
	org = v3(-3, -1, -2);
	vec3 d = v3(1, 0.6, 0.7);
	h = must_hit(c, org, d, 0);
	assert_vec_near(v3_madd(org, d, h.t), -0.5, 0.5, -0.25, 1e-12);
	assert_true(object_inside(c, v3(0.1, 0.25, 0.05)));
	assert_false(object_inside(c, v3(0.3, 0.25, 0.05)));
	assert_false(object_inside(c, v3(0.1, 0.1, 0.05))); /* below h1 */
	/* Bounds: the square at the widest height. */
	struct aabb b = c->ops->bounds(c);
	assert_vec_near(b.lo, -1, 0.2, -1, 1e-12);
	assert_vec_near(b.hi, 1, 1, 1, 1e-12);
	object_free(c);
	/* Heights -0.5 and 2: below y = 0 the section is mirrored. */
	struct object *c2 = make(PRISM_LINEAR_SPLINE, true, -0.5, 2, sq, 5, NULL);
	assert_near(hit_z(c2, 0, 1.5, -5, &n), -1.5, 1e-12);
	assert_normal_axis(n, 0, -0.707107, -0.707107);
	assert_near(hit_z(c2, 0, -0.25, -5, &n), -0.25, 1e-12);
	assert_normal_axis(n, 0, -0.707107, 0.707107);
	b = c2->ops->bounds(c2);
	assert_vec_near(b.lo, -2, -0.5, -2, 1e-12);
	assert_vec_near(b.hi, 2, 2, 2, 1e-12);
	object_free(c2);
}

/* Two sub-prisms nested: the even-odd rule makes a hole; all_hits gives
 * the four walls in order, and honours max. */
static void test_subprisms_and_all_hits(void **state)
{
	(void)state;
	static const double frame[][2] = {{0, 0}, {6, 0}, {6, 8}, {0, 8}, {0, 0},
	                                  {1, 1}, {5, 1}, {5, 7}, {1, 7}, {1, 1}};
	struct object *o = make(PRISM_LINEAR_SPLINE, false, 0, 1, frame, 10, NULL);
	assert_true(object_inside(o, v3(0.5, 0.5, 4)));
	assert_false(object_inside(o, v3(3, 0.5, 4)));
	assert_false(object_inside(o, v3(7, 0.5, 4)));
	assert_true(object_inside(o, v3(0.5, 1, 4))); /* on the top cap */
	assert_false(object_inside(o, v3(0.5, 1.01, 4)));
	struct ray r = mkray(v3(-1, 0.5, 4), v3(1, 0, 0));
	struct hit out[8];
	int n = o->ops->all_hits(o, &r, 0, INFINITY, out, 8);
	assert_int_equal(n, 4);
	static const double t[] = {1, 2, 6, 7};
	for (int i = 0; i < 4; i++) {
		assert_near(out[i].t, t[i], 1e-12);
		assert_ptr_equal(out[i].obj, o);
	}
	n = o->ops->all_hits(o, &r, 1.5, INFINITY, out, 2);
	assert_int_equal(n, 2);
	assert_near(out[0].t, 2, 1e-12);
	assert_near(out[1].t, 6, 1e-12);
	/* A vertical ray into the hole misses; into the rim hits the cap. */
	assert_false(hits(o, v3(3, 5, 4), v3(0, -1, 0), 0, INFINITY));
	assert_true(hits(o, v3(0.5, 5, 4), v3(0, -1, 0), 0, INFINITY));
	object_free(o);
}

/* Transformed and copied prisms go through the common layer. */
static void test_transform_and_copy(void **state)
{
	(void)state;
	static const double tri[][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}};
	struct object *o = prism_new(PRISM_LINEAR_SPLINE, false, 0, 1, tri, 4, nopos, NULL);
	transform(o, xform_scale(v3(2, 3, 4)));
	transform(o, xform_translate(v3(10, 0, 0)));
	object_prepare(o);
	struct object *c = object_copy(o);
	object_free(o);
	struct hit h = must_hit(c, v3(10.5, 1.5, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 5, 1e-12);
	assert_true(object_inside(c, v3(10.5, 2.9, 0.5)));
	assert_false(object_inside(c, v3(10.5, 3.1, 0.5)));
	struct aabb b = object_world_bounds(c);
	assert_vec_near(b.lo, 10, 0, 0, 1e-12);
	assert_vec_near(b.hi, 12, 3, 4, 1e-12);
	object_free(c);
}

/* ---- how the points are cut into sub-prisms ---- */

static void test_report(void **state)
{
	(void)state;
	struct prism_report rep;
	/* A linear prism that does not come back to its start is closed. */
	static const double open_tri[][2] = {{0, 0}, {1, 0}, {0, 1}};
	struct object *o = make(PRISM_LINEAR_SPLINE, false, 0, 1, open_tri, 3, &rep);
	assert_true(rep.closed_last);
	assert_int_equal(rep.open_at, -1);
	assert_true(object_inside(o, v3(0.2, 0.5, 0.2)));
	object_free(o);
	/* A single point left over is ignored without a word. */
	static const double extra[][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}, {0.1, 0.1}};
	o = make(PRISM_LINEAR_SPLINE, false, 0, 1, extra, 5, &rep);
	assert_false(rep.closed_last);
	assert_true(object_inside(o, v3(0.2, 0.5, 0.2)));
	object_free(o);
	/* A quadratic sub-prism that never returns to its start. */
	static const double q[][2] = {{0, -1}, {0, 0}, {1, 0}, {1, 1}, {0, 0}, {0.5, 0.5}, {0.2, 0.2}};
	o = make(PRISM_QUADRATIC_SPLINE, false, 0, 1, q, 7, &rep);
	assert_int_equal(rep.open_at, 5);
	object_free(o);
	/* A cubic one needs its end control point. */
	static const double cu[][2] = {{0, -1}, {0, 0}, {1, 0}, {1, 1}, {0, 0}};
	o = make(PRISM_CUBIC_SPLINE, false, 0, 1, cu, 5, &rep);
	assert_int_equal(rep.open_at, 0);
	object_free(o);
	/* Bezier: a closed drop and an unclosed piece, which is left out but
	 * still counts in the bounds (as POV-Ray's min_extent/max_extent). */
	static const double bz[][2] = {{0, 0}, {0.3, 0}, {0.7, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0},
	                               {3, 3}, {4, 3}, {3, 4}, {3, 3.5}};
	o = make(PRISM_BEZIER_SPLINE, false, 0, 1, bz, 12, &rep);
	assert_int_equal(rep.dropped, 1);
	assert_true(object_inside(o, v3(0.2, 0.5, 0.2)));
	assert_false(object_inside(o, v3(3.2, 0.5, 3.3)));
	struct aabb b = o->ops->bounds(o);
	assert_vec_near(b.hi, 4, 1, 4, 0);
	object_free(o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_quadratic),
		cmocka_unit_test(test_cubic_and_bezier),
		cmocka_unit_test(test_linear_caps_and_orientation),
		cmocka_unit_test(test_conic),
		cmocka_unit_test(test_subprisms_and_all_hits),
		cmocka_unit_test(test_transform_and_copy),
		cmocka_unit_test(test_report),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

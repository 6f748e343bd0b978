/* test_poly.c: unit tests for the polynomial root solvers
 * (src/geom/solve.h) and the primitives built on them: torus
 * (src/geom/torus.c) and poly/cubic/quartic (src/geom/poly.c). Solvers are
 * checked against known roots, including double roots, wide dynamic range,
 * ill-conditioned quartics and interval limits; the shapes against
 * analytic hits, misses, tangent rays, normals, inside tests, bounds and
 * uv coordinates (the torus's measured from POV-Ray renders). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes.h"
#include "geom/solve.h"
#include "scene/object.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* ---- helpers ---- */

/* The coefficients (ascending) of lead * prod (t - roots[i]). */
static void from_roots(const double *roots, int n, double lead, double *c)
{
	c[0] = lead;
	for (int i = 1; i <= n; i++)
		c[i] = 0;
	for (int k = 0; k < n; k++) {
		for (int i = k + 1; i > 0; i--)
			c[i] = c[i - 1] - roots[k] * c[i];
		c[0] = -roots[k] * c[0];
	}
}

/* Solve and compare with the expected distinct roots, each to a tolerance
 * relative to its own magnitude (plus abs). */
static void expect_roots(int got, const double *r, int n, const double *want, double rel, double abs)
{
	if (got != n) {
		char buf[256];
		int len = 0;
		for (int i = 0; i < got && len < 200; i++)
			len += snprintf(buf + len, sizeof buf - len, " %.17g", r[i]);
		buf[len] = 0;
		fail_msg("%d roots, expected %d:%s", got, n, buf);
	}
	for (int i = 0; i < n; i++)
		assert_near(r[i], want[i], rel * fabs(want[i]) + abs);
}

/* Every crossing in (tmin, inf), object space (no transform in these). */
static int all_hits(const struct object *o, vec3 org, vec3 dir, double tmin, double *t)
{
	struct ray r = mkray(org, dir);
	struct hit h[8];
	int n = o->ops->all_hits(o, &r, tmin, INFINITY, h, 8);
	for (int i = 0; i < n; i++) {
		assert_ptr_equal(h[i].obj, o);
		t[i] = h[i].t;
		if (i > 0)
			assert_true(t[i] > t[i - 1]);
	}
	return n;
}

/* ---- solve_cubic ---- */

static void test_cubic_basic(void **state)
{
	(void)state;
	double c[4], r[3];
	const double w1[] = {1, 2, 3};
	from_roots(w1, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 3, w1, 1e-15, 0);
	/* Negative leading coefficient, negative roots. */
	const double w2[] = {-7, -0.5, 4};
	from_roots(w2, 3, -2.5, c);
	expect_roots(solve_cubic(c, r), r, 3, w2, 1e-15, 0);
	/* One real root: t^3 - 1. */
	double c3[4] = {-1, 0, 0, 1};
	const double w3[] = {1};
	expect_roots(solve_cubic(c3, r), r, 1, w3, 0, 0);
	/* t^3 + t + 10 = (t + 2)(t^2 - 2t + 5). */
	double c4[4] = {10, 1, 0, 1};
	const double w4[] = {-2};
	expect_roots(solve_cubic(c4, r), r, 1, w4, 1e-15, 0);
	/* A zero leading coefficient makes it a quadratic. */
	double c5[4] = {-6, 1, 1, 0};
	const double w5[] = {-3, 2};
	expect_roots(solve_cubic(c5, r), r, 2, w5, 1e-15, 0);
	/* t^3: a triple root at zero, reported once. */
	double c6[4] = {0, 0, 0, 5};
	const double w6[] = {0};
	expect_roots(solve_cubic(c6, r), r, 1, w6, 0, 0);
}

static void test_cubic_multiple(void **state)
{
	(void)state;
	double c[4], r[3];
	/* (t-1)^2 (t-3): the double root once, to full precision. */
	const double w1[] = {1, 1, 3}, e1[] = {1, 3};
	from_roots(w1, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 2, e1, 1e-14, 0);
	/* (t+2)(t-5)^2, scaled. */
	const double w2[] = {-2, 5, 5}, e2[] = {-2, 5};
	from_roots(w2, 3, 0.75, c);
	expect_roots(solve_cubic(c, r), r, 2, e2, 1e-14, 0);
	/* (t-2)^3. */
	const double w3[] = {2, 2, 2}, e3[] = {2};
	from_roots(w3, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 1, e3, 1e-12, 0);
	/* Two roots 1e-5 apart are still two (at 1e-7 apart p stays within
	 * its rounding noise between them, and they are one double root). */
	const double w4[] = {1, 1 + 1e-5, 4};
	from_roots(w4, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 3, w4, 1e-9, 0); /* their conditioning */
}

static void test_cubic_wide_range(void **state)
{
	(void)state;
	double c[4], r[3];
	/* The small root would lose all its digits to -a/3 without the
	 * polishing on the original polynomial. */
	const double w1[] = {1e-8, 1, 2};
	from_roots(w1, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 3, w1, 1e-14, 0);
	const double w2[] = {-1e6, 1e-3, 5};
	from_roots(w2, 3, 1, c);
	expect_roots(solve_cubic(c, r), r, 3, w2, 1e-13, 0);
	/* Coefficients near the ends of the double range: rescaling keeps the
	 * closed form from overflowing. */
	const double w3[] = {1e100, 2e100, 3e100};
	from_roots(w3, 3, 1e-200, c);
	expect_roots(solve_cubic(c, r), r, 3, w3, 1e-14, 0);
	const double w4[] = {-3e-120, 1e-120, 7e-120};
	from_roots(w4, 3, 1e150, c);
	expect_roots(solve_cubic(c, r), r, 3, w4, 1e-14, 0);
}

/* ---- solve_quartic ---- */

static void test_quartic_basic(void **state)
{
	(void)state;
	double c[5], r[4];
	const double w1[] = {1, 2, 3, 4};
	from_roots(w1, 4, 1, c);
	expect_roots(solve_quartic(c, r), r, 4, w1, 1e-14, 0);
	/* Biquadratic t^4 - 5t^2 + 4. */
	double c2[5] = {4, 0, -5, 0, 1};
	const double w2[] = {-2, -1, 1, 2};
	expect_roots(solve_quartic(c2, r), r, 4, w2, 1e-15, 0);
	/* No real roots: t^4 + t^2 + 1. */
	double c3[5] = {1, 0, 1, 0, 1};
	assert_int_equal(solve_quartic(c3, r), 0);
	/* Two real roots and a complex pair: (t^2 + 1)(t - 1)(t + 3), times -3. */
	double c4[5] = {9, -6, 6, -6, -3};
	const double w4[] = {-3, 1};
	expect_roots(solve_quartic(c4, r), r, 2, w4, 1e-15, 0);
	/* The manual's torus quartic along the x axis: t^4 - 104 t^2 + 784,
	 * roots +-sqrt(52 +- sqrt(1920)). */
	double c5[5] = {784, 0, -104, 0, 1};
	double a = sqrt(52 - sqrt(1920.0)), b = sqrt(52 + sqrt(1920.0));
	const double w5[] = {-b, -a, a, b};
	expect_roots(solve_quartic(c5, r), r, 4, w5, 1e-15, 0);
	/* A zero constant term: a root at zero. */
	double c6[5] = {0, -6, 11, -6, 1};
	const double w6[] = {0, 1, 2, 3};
	expect_roots(solve_quartic(c6, r), r, 4, w6, 1e-15, 0);
	/* Zero leading coefficient: a cubic. */
	double c7[5] = {-6, 11, -6, 1, 0};
	const double w7[] = {1, 2, 3};
	expect_roots(solve_quartic(c7, r), r, 3, w7, 1e-15, 0);
}

static void test_quartic_multiple(void **state)
{
	(void)state;
	double c[5], r[4];
	const double w1[] = {1, 1, 2, 3}, e1[] = {1, 2, 3};
	from_roots(w1, 4, 1, c);
	expect_roots(solve_quartic(c, r), r, 3, e1, 1e-14, 0);
	/* Two double roots: a ray touching a torus at two points. */
	const double w2[] = {1, 1, 3, 3}, e2[] = {1, 3};
	from_roots(w2, 4, 1, c);
	expect_roots(solve_quartic(c, r), r, 2, e2, 1e-14, 0);
	/* (t^2 + 1)(t - 2)^2: a double root beside a complex pair. */
	double c3[5] = {4, -4, 5, -4, 1};
	const double e3[] = {2};
	expect_roots(solve_quartic(c3, r), r, 1, e3, 1e-14, 0);
	/* (t - 0.5)^4. */
	const double w4[] = {0.5, 0.5, 0.5, 0.5}, e4[] = {0.5};
	from_roots(w4, 4, 1, c);
	expect_roots(solve_quartic(c, r), r, 1, e4, 1e-9, 0);
}

static void test_quartic_wide_range(void **state)
{
	(void)state;
	double c[5], r[4];
	const double w1[] = {1e-6, 1, 1e3, 1e6};
	from_roots(w1, 4, 1, c);
	expect_roots(solve_quartic(c, r), r, 4, w1, 1e-13, 0);
	const double w2[] = {-1e5, -1e-5, 1e-9, 3};
	from_roots(w2, 4, -4, c);
	expect_roots(solve_quartic(c, r), r, 4, w2, 1e-13, 0);
}

/* Ill-conditioned quartics of the kind a thin torus seen from afar gives:
 * two pairs of close roots far from the origin. */
static void test_quartic_ill_conditioned(void **state)
{
	(void)state;
	double c[5], r[4];
	/* Roots to the polynomial's conditioning: the coefficients from the
	 * product are rounded, which moves these roots by ~1e-9. */
	const double w1[] = {300, 300.2, 499.8, 500};
	from_roots(w1, 4, 1, c);
	for (int sturm = 0; sturm < 2; sturm++)
		expect_roots(solve_poly(c, 4, -INFINITY, INFINITY, sturm, r), r, 4, w1, 1e-11, 0);
	/* A complex pair 0.0435 from the real axis near 0.38 among roots of
	 * size ~140: a ray passing 0.0064 outside the tube of the 100/0.1
	 * torus. The exact Sturm sequence's last term is ~1e-16 of its
	 * operands, so a naive Sturm solver reported a phantom root here; no
	 * path may. */
	double c2[5] = {4213.9827033406291, -21738.075501343999, 28282.913314408652, 274.62865110888231, 1};
	assert_int_equal(solve_poly(c2, 4, -1e-5, 0.41, false, r), 0);
	assert_int_equal(solve_poly(c2, 4, -1e-5, 0.41, true, r), 0);
	assert_int_equal(solve_poly(c2, 4, -INFINITY, INFINITY, false, r), 0);
	assert_int_equal(solve_poly(c2, 4, -INFINITY, INFINITY, true, r), 0);
}

/* ---- solve_poly ---- */

static void test_poly_interval(void **state)
{
	(void)state;
	double c[8], r[7];
	const double w[] = {-3, -1, 0.5, 2, 2.5, 7, 9};
	from_roots(w, 7, 2.5, c);
	expect_roots(solve_poly(c, 7, -INFINITY, INFINITY, true, r), r, 7, w, 1e-13, 0);
	const double in[] = {0.5, 2, 2.5};
	expect_roots(solve_poly(c, 7, 0, 5, true, r), r, 3, in, 1e-13, 0);
	/* The interval is open: roots at its ends are out. */
	const double in2[] = {2};
	expect_roots(solve_poly(c, 7, 0.5, 2.5, true, r), r, 1, in2, 1e-13, 0);
	assert_int_equal(solve_poly(c, 7, 9, INFINITY, true, r), 0);
	assert_int_equal(solve_poly(c, 7, 2.6, 6.9, false, r), 0);
	/* The same for the closed forms. */
	const double w4[] = {-2, 1, 3, 8};
	double c4[5];
	from_roots(w4, 4, 1, c4);
	for (int sturm = 0; sturm < 2; sturm++) {
		const double e4[] = {1, 3};
		expect_roots(solve_poly(c4, 4, 0, 5, sturm, r), r, 2, e4, 1e-14, 0);
		expect_roots(solve_poly(c4, 4, 1, 3, sturm, r), r, 0, e4, 0, 0);
		const double e5[] = {8};
		expect_roots(solve_poly(c4, 4, 3, INFINITY, sturm, r), r, 1, e5, 1e-14, 0);
		const double e6[] = {-2};
		expect_roots(solve_poly(c4, 4, -INFINITY, 0.999, sturm, r), r, 1, e6, 1e-14, 0);
	}
	/* A root just inside an end is found. */
	const double w7[] = {1e-12, 5};
	double c7[3];
	from_roots(w7, 2, 1, c7);
	expect_roots(solve_poly(c7, 2, 0, 10, false, r), r, 2, w7, 1e-12, 0);
	expect_roots(solve_poly(c7, 2, 0, 10, true, r), r, 2, w7, 1e-12, 0);
}

static void test_poly_high_degree(void **state)
{
	(void)state;
	double c[8], r[7];
	/* Double roots among simple ones: (t-1)^2 (t-2)(t+3)(t-4)^2 (t-5). */
	const double w[] = {1, 1, 2, -3, 4, 4, 5}, e[] = {-3, 1, 2, 4, 5};
	from_roots(w, 7, 1, c);
	expect_roots(solve_poly(c, 7, -INFINITY, INFINITY, true, r), r, 5, e, 1e-12, 0);
	/* Degree 5 and 6, closed forms unavailable: Sturm whatever the flag. */
	const double w5[] = {-2.5, -0.1, 0.7, 1.3, 6};
	from_roots(w5, 5, -1.5, c);
	expect_roots(solve_poly(c, 5, -INFINITY, INFINITY, false, r), r, 5, w5, 1e-13, 0);
	/* t^6 - 1: two real roots. */
	double c6[7] = {-1, 0, 0, 0, 0, 0, 1};
	const double e6[] = {-1, 1};
	expect_roots(solve_poly(c6, 6, -INFINITY, INFINITY, false, r), r, 2, e6, 1e-15, 0);
	/* Wide range at degree 7. */
	const double w7[] = {-1e4, -1, -1e-4, 1e-3, 0.5, 20, 3e3};
	from_roots(w7, 7, 1, c);
	expect_roots(solve_poly(c, 7, -INFINITY, INFINITY, true, r), r, 7, w7, 1e-11, 0);
}

static void test_poly_degenerate(void **state)
{
	(void)state;
	double r[7];
	double zero[5] = {0, 0, 0, 0, 0};
	assert_int_equal(solve_poly(zero, 4, -INFINITY, INFINITY, false, r), 0);
	double cst[1] = {3};
	assert_int_equal(solve_poly(cst, 0, -INFINITY, INFINITY, false, r), 0);
	double lin[2] = {-3, 2};
	const double el[] = {1.5};
	expect_roots(solve_poly(lin, 1, -INFINITY, INFINITY, false, r), r, 1, el, 0, 0);
	assert_int_equal(solve_poly(lin, 1, 2, INFINITY, false, r), 0);
	double nan[3] = {1, NAN, 1}, inf[3] = {-1, 0, INFINITY};
	assert_int_equal(solve_poly(nan, 2, -INFINITY, INFINITY, false, r), 0);
	assert_int_equal(solve_poly(inf, 2, -INFINITY, INFINITY, true, r), 0);
	/* Degree out of range, empty interval. */
	double c8[9] = {1, 0, 0, 0, 0, 0, 0, 0, -1};
	assert_int_equal(solve_poly(c8, 8, -INFINITY, INFINITY, true, r), 0);
	double q[3] = {-1, 0, 1};
	assert_int_equal(solve_poly(q, 2, 1, 1, false, r), 0);
	assert_int_equal(solve_poly(q, 2, 2, -2, false, r), 0);
	assert_int_equal(solve_poly(q, 2, NAN, 2, false, r), 0);
	/* A leading coefficient too small to matter over a finite interval is
	 * dropped: -1e-30 t^4 + (t^2 - 1) has roots near +-1e15 far outside. */
	double tiny[5] = {-1, 0, 1, 0, -1e-30};
	const double et[] = {-1, 1};
	expect_roots(solve_poly(tiny, 4, -10, 10, false, r), r, 2, et, 1e-15, 0);
	expect_roots(solve_poly(tiny, 4, -10, 10, true, r), r, 2, et, 1e-15, 0);
	/* Over the whole line they are roots. */
	const double et2[] = {-1e15, -1, 1, 1e15};
	expect_roots(solve_poly(tiny, 4, -INFINITY, INFINITY, false, r), r, 4, et2, 1e-14, 0);
}

/* Closed form and Sturm agree on a family of quartics whose roots pass
 * from real to complex (a ray sweeping across a torus's silhouette). */
static void test_poly_closed_vs_sturm(void **state)
{
	(void)state;
	for (int i = 0; i <= 200; i++) {
		double h = -1e-3 + 1e-5 * i; /* (t^2 - 2t + 1 - h)(t^2 + 3t - 4) */
		double A[3] = {1 - h, -2, 1}, B[3] = {-4, 3, 1}, c[5] = {0};
		for (int a = 0; a < 3; a++)
			for (int b = 0; b < 3; b++)
				c[a + b] += A[a] * B[b];
		double r0[4], r1[4];
		int n0 = solve_poly(c, 4, -10, 10, false, r0);
		int n1 = solve_poly(c, 4, -10, 10, true, r1);
		if (fabs(h) < 1e-12) {
			/* A triple root at 1: below the resolution, any count. */
			for (int k = 0; k < n0; k++)
				assert_true(isfinite(r0[k]));
			for (int k = 0; k < n1; k++)
				assert_true(isfinite(r1[k]));
		} else if (h > 0) {
			const double want[] = {-4, 1 - sqrt(h), 1, 1 + sqrt(h)};
			expect_roots(n0, r0, 4, want, 1e-7, 1e-12);
			expect_roots(n1, r1, 4, want, 1e-7, 1e-12);
		} else {
			const double want[] = {-4, 1};
			expect_roots(n0, r0, 2, want, 1e-7, 0);
			expect_roots(n1, r1, 2, want, 1e-7, 0);
		}
	}
}

/* ---- torus ---- */

static void test_torus_hits(void **state)
{
	(void)state;
	struct object *T = torus_new(2, 0.5, false, nopos);
	vec3 org = v3(-5, 0, 0), dx = v3(1, 0, 0);
	double t[8];
	int n = all_hits(T, org, dx, 0, t);
	assert_int_equal(n, 4);
	assert_near(t[0], 2.5, 1e-14);
	assert_near(t[1], 3.5, 1e-14);
	assert_near(t[2], 6.5, 1e-14);
	assert_near(t[3], 7.5, 1e-14);
	struct hit h = must_hit(T, org, dx, 0);
	assert_near(h.t, 2.5, 1e-15);
	assert_vec_near(hit_normal(T, org, dx, &h), -1, 0, 0, 1e-15);
	h = must_hit(T, org, dx, 3);
	assert_near(h.t, 3.5, 1e-15);
	assert_vec_near(hit_normal(T, org, dx, &h), 1, 0, 0, 1e-15);
	/* Non-unit direction: t scales. */
	h = must_hit(T, org, v3(4, 0, 0), 0);
	assert_near(h.t, 0.625, 1e-15);
	/* tmax cuts off; bounds are exclusive. */
	assert_false(hits(T, org, dx, 0, 2.5));
	assert_true(hits(T, org, dx, 0, 2.5000001));
	/* From above, onto the top of the tube. */
	h = must_hit(T, v3(2, 5, 0), v3(0, -1, 0), 0);
	assert_near(h.t, 4.5, 1e-15);
	assert_vec_near(hit_normal(T, v3(2, 5, 0), v3(0, -1, 0), &h), 0, 1, 0, 1e-15);
	/* Diagonal direction in the xz plane. */
	double s = sqrt(0.5);
	h = must_hit(T, v3(-5 * s, 0, -5 * s), v3(s, 0, s), 0);
	assert_near(h.t, 2.5, 1e-14);
	assert_vec_near(hit_normal(T, v3(-5 * s, 0, -5 * s), v3(s, 0, s), &h), -s, 0, -s, 1e-14);
	/* Misses: down the hole, above, beside, and away. */
	assert_false(hits(T, v3(0, 5, 0), v3(0, -1, 0), 0, INFINITY));
	assert_false(hits(T, v3(-5, 0.6, 0), dx, 0, INFINITY));
	assert_false(hits(T, v3(-5, 0, 2.6), dx, 0, INFINITY));
	assert_false(hits(T, org, v3(-1, 0, 0), 0, INFINITY));
	/* A zero direction hits nothing. */
	assert_false(hits(T, org, v3(0, 0, 0), 0, INFINITY));
	object_free(T);
}

static void test_torus_inside_start(void **state)
{
	(void)state;
	struct object *T = torus_new(2, 0.5, false, nopos);
	/* From the centre of the tube: exits through the top. */
	struct hit h = must_hit(T, v3(2, 0, 0), v3(0, 1, 0), 0);
	assert_near(h.t, 0.5, 1e-15);
	assert_vec_near(hit_normal(T, v3(2, 0, 0), v3(0, 1, 0), &h), 0, 1, 0, 1e-15);
	/* Starting on the surface: the crossing at t = 0 is excluded by tmin,
	 * the next one is the far side of the tube. */
	vec3 on = v3(2.5, 0, 0);
	assert_false(hits(T, on, v3(1, 0, 0), 1e-9, INFINITY));
	h = must_hit(T, on, v3(-1, 0, 0), 1e-9);
	assert_near(h.t, 1, 1e-15);
	double t[8];
	int n = all_hits(T, on, v3(-1, 0, 0), 1e-9, t);
	assert_int_equal(n, 3);
	assert_near(t[0], 1, 1e-15);
	assert_near(t[1], 4, 1e-15);
	assert_near(t[2], 5, 1e-15);
	object_free(T);
}

/* Tangent rays give a double root: a hit at the touching point (reported
 * once) or, within rounding, a miss; never a wrong point or NaN. */
static void test_torus_tangent(void **state)
{
	(void)state;
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *T = torus_new(2, 0.5, sturm, nopos);
		/* Along x at the height of the tube's top: touches at x = -2, 2. */
		double t[8];
		int n = all_hits(T, v3(-5, 0.5, 0), v3(1, 0, 0), 0, t);
		assert_true(n == 0 || n == 2);
		if (n == 2) {
			assert_near(t[0], 3, 1e-6);
			assert_near(t[1], 7, 1e-6);
		}
		/* Along z, touching the outer equator at (2.5, 0, 0). */
		n = all_hits(T, v3(2.5, 0, -5), v3(0, 0, 1), 0, t);
		assert_true(n <= 1);
		if (n == 1)
			assert_near(t[0], 5, 1e-6);
		/* Along z at x = 1.5: crosses the outer surface at z = -2 and 2
		 * and touches the inner equator at z = 0 in between. */
		n = all_hits(T, v3(1.5, 0, -5), v3(0, 0, 1), 0, t);
		if (n < 2 || n > 4)
			fail_msg("%d crossings", n);
		assert_near(t[0], 3, 1e-14);
		assert_near(t[n - 1], 7, 1e-14);
		for (int i = 1; i < n - 1; i++)
			assert_near(t[i], 5, 1e-6);
		/* 1e-6 further in, the ray dips into the hole for a moment: four
		 * crossings, the middle two 3.5e-3 apart. */
		double x = 1.5 - 1e-6, z1 = sqrt((1.5 - x) * (1.5 + x)), z2 = sqrt((2.5 - x) * (2.5 + x));
		n = all_hits(T, v3(x, 0, -5), v3(0, 0, 1), 0, t);
		assert_int_equal(n, 4);
		assert_near(t[0], 5 - z2, 1e-14);
		assert_near(t[1], 5 - z1, 1e-12);
		assert_near(t[2], 5 + z1, 1e-12);
		assert_near(t[3], 5 + z2, 1e-14);
		object_free(T);
	}
}

/* The first t > 0 where the ray (in the plane x = 0) meets the circle of
 * radius r around (y, z) = (0, zc), in long double; -1 for none. */
static long double circle_t(vec3 org, vec3 dir, double zc, double r)
{
	long double fy = org.y, fz = (long double)org.z - zc, dy = dir.y, dz = dir.z;
	long double a = dy * dy + dz * dz, b = fy * dy + fz * dz, c = fy * fy + fz * fz - (long double)r * r;
	long double disc = b * b - a * c;
	if (disc < 0)
		return -1;
	long double q = -(b + (b < 0 ? -sqrtl(disc) : sqrtl(disc)));
	long double t0 = q / a, t1 = c / q;
	if (t0 > t1) {
		long double tt = t0;
		t0 = t1;
		t1 = tt;
	}
	return t0 > 0 ? t0 : t1 > 0 ? t1 : -1;
}

/* The 100/0.1 torus seen from distance ~300: its quartic is badly
 * conditioned, yet every hit must agree with the analytic distance to the
 * tube to 1e-9 relative. Rays in the plane x = 0 meet the tube's circular
 * cross-sections around (y, z) = (0, -100) and (0, 100), which give t
 * exactly. */
static void test_torus_thin_far(void **state)
{
	(void)state;
	const double R = 100, r = 0.1;
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *T = torus_new(R, r, sturm, nopos);
		unsigned seed = 12345;
		for (int i = 0; i < 2000; i++) {
			seed = seed * 1103515245u + 12345u;
			double u1 = (seed >> 8) / 16777216.0;
			seed = seed * 1103515245u + 12345u;
			double u2 = (seed >> 8) / 16777216.0;
			seed = seed * 1103515245u + 12345u;
			double u3 = (seed >> 8) / 16777216.0;
			double el = (u1 - 0.5) * 2.4;
			vec3 org = v3(0, 300 * sin(el), -300 * cos(el));
			/* Aim inside the cross-section (a sure hit) or outside it. */
			double ang = 6.283185307179586 * u2, rad = 0.2 * u3;
			vec3 aim = v3(0, rad * sin(ang), -R + rad * cos(ang));
			vec3 dir = v3_scale(v3_sub(aim, org), 0.5 + u3);
			long double tn = circle_t(org, dir, -R, r), tf = circle_t(org, dir, R, r);
			long double tw = tn > 0 && (tf < 0 || tn < tf) ? tn : tf;
			struct ray ray = mkray(org, dir);
			struct hit h;
			bool hit = object_intersect(T, &ray, 1e-9, INFINITY, &h);
			if (rad < 0.099)
				assert_true(tn > 0); /* aimed inside: a sure hit */
			if (tw > 0) {
				if (!hit)
					fail_msg("ray %d missed (sturm %d)", i, sturm);
				assert_near(h.t, (double)tw, 1e-9 * (double)tw);
				/* And the hit point is on the tube. */
				vec3 p = v3_madd(org, dir, h.t);
				double d = hypot(hypot(p.x, p.z) - R, p.y);
				assert_near(d, r, 1e-9 * v3_len(v3_sub(p, org)));
			} else if (hit) {
				fail_msg("ray %d passing %g from the centre hit at %.17g (sturm %d)", i, rad, h.t, sturm);
			}
		}
		object_free(T);
	}
}

/* Rays in general position against the thin torus: each hit point lies on
 * the tube to 1e-9 relative to the distance travelled, and closed form and
 * Sturm agree. */
static void test_torus_thin_general(void **state)
{
	(void)state;
	const double R = 100, r = 0.1;
	struct object *T = torus_new(R, r, false, nopos), *S = torus_new(R, r, true, nopos);
	unsigned seed = 777;
	int nhit = 0;
	for (int i = 0; i < 3000; i++) {
		double u[5];
		for (int k = 0; k < 5; k++) {
			seed = seed * 1103515245u + 12345u;
			u[k] = (seed >> 8) / 16777216.0;
		}
		double az = 6.283185307179586 * u[0], el = (u[1] - 0.5) * 2.5;
		vec3 org = v3(300 * cos(az) * cos(el), 300 * sin(el), 300 * sin(az) * cos(el));
		double b = 6.283185307179586 * u[2], rr = R + (u[3] - 0.5) * 0.3, yy = (u[4] - 0.5) * 0.3;
		vec3 aim = v3(rr * cos(b), yy, rr * sin(b));
		vec3 dir = v3_sub(aim, org);
		struct ray ray = mkray(org, dir);
		struct hit h0, h1;
		bool a = object_intersect(T, &ray, 1e-9, INFINITY, &h0);
		bool c = object_intersect(S, &ray, 1e-9, INFINITY, &h1);
		assert_int_equal(a, c);
		/* Aimed inside the tube: must hit, no later than the aim point. */
		if (hypot(rr - R, yy) < r * 0.99) {
			assert_true(a);
			assert_true(h0.t <= 1 + 1e-12);
		}
		if (!a)
			continue;
		nhit++;
		assert_near(h0.t, h1.t, 1e-12 * h0.t);
		vec3 p = v3_madd(org, dir, h0.t);
		double d = hypot(hypot(p.x, p.z) - R, p.y);
		assert_near(d, r, 1e-9 * v3_len(v3_sub(p, org)));
		/* Just before the first hit the ray is still outside. */
		assert_false(object_inside(T, v3_madd(org, dir, h0.t * (1 - 1e-7))));
	}
	assert_true(nhit > 1000);
	object_free(T);
	object_free(S);
}

/* A ray through the 100/0.1 torus's tube whose quartic defeated a Sturm
 * solver without error tracking: its sequence's last term fell below its
 * rounding error, the count came out one short and a crossing was lost. */
static void test_torus_sturm_regression(void **state)
{
	(void)state;
	vec3 org = v3(0x1.d9a37ddacb157p+7, -0x1.6b27b70b6fbaap+7, 0x1.ec2a387b6a266p+4);
	vec3 dir = v3(-0x1.241f25df58b95p+8, 0x1.6b10d9d5f8f35p+7, -0x1.c7efd209b1136p+6);
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *T = torus_new(100, 0.1, sturm, nopos);
		double t[8];
		int n = all_hits(T, org, dir, 1e-9, t);
		assert_int_equal(n, 2);
		for (int i = 0; i < n; i++) {
			vec3 p = v3_madd(org, dir, t[i]);
			assert_near(hypot(hypot(p.x, p.z) - 100, p.y), 0.1, 1e-9 * v3_len(v3_sub(p, org)));
		}
		object_free(T);
	}
}

static void test_torus_normal_inside_bounds(void **state)
{
	(void)state;
	struct object *T = torus_new(2, 0.5, false, nopos);
	const struct object_ops *ops = T->ops;
	double s = sqrt(0.5);
	assert_vec_near(v3_norm(ops->normal(T, v3(2.5, 0, 0), NULL)), 1, 0, 0, 1e-15);
	assert_vec_near(v3_norm(ops->normal(T, v3(1.5, 0, 0), NULL)), -1, 0, 0, 1e-15);
	assert_vec_near(v3_norm(ops->normal(T, v3(0, 0.5, 2), NULL)), 0, 1, 0, 1e-15);
	assert_vec_near(v3_norm(ops->normal(T, v3(0, -0.5, -2), NULL)), 0, -1, 0, 1e-15);
	assert_vec_near(v3_norm(ops->normal(T, v3(2.5 * s, 0, 2.5 * s), NULL)), s, 0, s, 1e-15);
	assert_vec_near(v3_norm(ops->normal(T, v3(2 + 0.5 * s, 0.5 * s, 0), NULL)), s, s, 0, 1e-15);
	/* Inside: POV-Ray counts the surface itself as inside. */
	assert_true(object_inside(T, v3(2, 0, 0)));
	assert_true(object_inside(T, v3(0, 0.49, -2)));
	assert_true(object_inside(T, v3(2.5, 0, 0)));
	assert_false(object_inside(T, v3(2.5 + 1e-12, 0, 0)));
	assert_false(object_inside(T, v3(0, 0, 0)));
	assert_false(object_inside(T, v3(2, 0.51, 0)));
	assert_false(object_inside(T, v3(3, 0, 0)));
	struct aabb b = ops->bounds(T);
	assert_vec_near(b.lo, -2.5, -0.5, -2.5, 0);
	assert_vec_near(b.hi, 2.5, 0.5, 2.5, 0);
	object_free(T);
}

/* POV-Ray's uv_mapping on a torus, measured from 16-bit renders of
 * torus { 1, 0.4 uv_mapping ... } (points and uv from the same pixels). */
static void test_torus_uv(void **state)
{
	(void)state;
	struct object *T = torus_new(2, 0.5, false, nopos);
	double uv[2];
	assert_non_null(T->ops->uv);
	static const struct {
		vec3 p;
		double u, v;
	} exact[] = {
		{{-2.5, 0, 0}, 0, 0.5},  /* outer equator at -x */
		{{0, 0, 2.5}, 0.25, 0.5},
		{{2.5, 0, 0}, 0.5, 0.5},
		{{0, 0, -2.5}, 0.75, 0.5},
		{{2, -0.5, 0}, 0.5, 0.25}, /* bottom */
		{{2, 0.5, 0}, 0.5, 0.75},  /* top */
		{{1.5, 0, 0}, 0.5, 1},     /* inner equator */
	};
	for (size_t i = 0; i < sizeof exact / sizeof exact[0]; i++) {
		assert_true(T->ops->uv(T, exact[i].p, NULL, uv));
		assert_near(uv[0], exact[i].u, 1e-15);
		assert_near(uv[1], exact[i].v, 1e-15);
	}
	object_free(T);
	T = torus_new(1, 0.4, false, nopos);
	static const struct {
		double x, y, z, u, v;
	} pov[] = {
		{-1.013, 0.369, 0.553, 0.0795, 0.6869}, {-1.213, -0.256, 0.487, 0.0607, 0.3894},
		{-0.240, -0.172, -1.340, 0.7782, 0.4294}, {0.107, -0.339, -0.780, 0.7284, 0.1608},
		{0.613, 0.390, 0.900, 0.3452, 0.7142},    {1.307, -0.252, -0.100, 0.5122, 0.3914},
		{0.720, 0.286, 0.020, 0.4956, 0.8733},    {1.133, -0.156, -0.767, 0.5947, 0.4362},
	};
	for (size_t i = 0; i < sizeof pov / sizeof pov[0]; i++) {
		assert_true(T->ops->uv(T, v3(pov[i].x, pov[i].y, pov[i].z), NULL, uv));
		assert_near(uv[0], pov[i].u, 2e-3);
		assert_near(uv[1], pov[i].v, 2e-3);
	}
	object_free(T);
}

static void test_torus_transformed(void **state)
{
	(void)state;
	/* Rotated 90 degrees about x: the torus lies in the xy plane. */
	struct object *T = torus_new(2, 0.5, false, nopos);
	transform(T, xform_rotate(v3(90, 0, 0)));
	assert_false(hits(T, v3(0, 0, -5), v3(0, 0, 1), 0, INFINITY));
	struct hit h = must_hit(T, v3(0, 2, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4.5, 1e-14);
	assert_vec_near(hit_normal(T, v3(0, 2, -5), v3(0, 0, 1), &h), 0, 0, -1, 1e-14);
	assert_true(object_inside(T, v3(0, -2, 0)));
	object_free(T);
	/* Scaled by 2 and moved: major 4, minor 1, centred at (1, 2, 3). */
	T = torus_new(2, 0.5, true, nopos);
	transform(T, xform_scale(v3(2, 2, 2)));
	transform(T, xform_translate(v3(1, 2, 3)));
	h = must_hit(T, v3(-9, 2, 3), v3(1, 0, 0), 0);
	assert_near(h.t, 5, 1e-14);
	h = must_hit(T, v3(-9, 2, 3), v3(1, 0, 0), 5.5);
	assert_near(h.t, 7, 1e-14);
	struct aabb b = object_world_bounds(T);
	assert_vec_near(b.lo, -4, 1, -2, 1e-14);
	assert_vec_near(b.hi, 6, 3, 8, 1e-14);
	object_free(T);
}

/* Degenerate tori: major 0 is a sphere; minor 0 has nothing to hit; a
 * spindle torus (minor > major) shows its inner lemon as POV-Ray 3.7 does. */
static void test_torus_degenerate(void **state)
{
	(void)state;
	struct object *T = torus_new(0, 1, false, nopos);
	struct hit h = must_hit(T, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 1e-15);
	double t[8];
	assert_int_equal(all_hits(T, v3(0, 0, -5), v3(0, 0, 1), 0, t), 2);
	assert_near(t[1], 6, 1e-15);
	object_free(T);
	T = torus_new(2, 0, false, nopos);
	assert_false(hits(T, v3(-5, 0, 0), v3(1, 0, 0), 0, INFINITY));
	object_free(T);
	/* Spindle: major 0.5, minor 1, a vertical ray at x = 0.1 crosses the
	 * apple at y = +-sqrt(1 - 0.4^2) and the lemon at y = +-0.8. */
	for (int sturm = 0; sturm < 2; sturm++) {
		T = torus_new(0.5, 1, sturm, nopos);
		int n = all_hits(T, v3(0.1, 5, 0), v3(0, -1, 0), 0, t);
		assert_int_equal(n, 4);
		double ya = sqrt(0.84);
		assert_near(t[0], 5 - ya, 1e-14);
		assert_near(t[1], 4.2, 1e-14);
		assert_near(t[2], 5.8, 1e-14);
		assert_near(t[3], 5 + ya, 1e-14);
		/* Apple top: away from the near point of the circle. */
		vec3 n0 = v3_norm(T->ops->normal(T, v3(0.1, ya, 0), NULL));
		assert_vec_near(n0, -0.4, ya, 0, 1e-14);
		/* Lemon top: the quartic's gradient, towards the far point. */
		vec3 n1 = v3_norm(T->ops->normal(T, v3(0.1, 0.8, 0), NULL));
		assert_vec_near(n1, -0.6, -0.8, 0, 1e-14);
		object_free(T);
	}
}

/* ---- poly, cubic, quartic ---- */

/* The position of x^i y^j z^k in POV-Ray's coefficient vector of the
 * given order (i descending, then j, then k). */
static int pov_index(int n, int i, int j, int k)
{
	int idx = 0;
	for (int a = n; a >= 0; a--)
		for (int b = n - a; b >= 0; b--)
			for (int c = n - a - b; c >= 0; c--) {
				if (a == i && b == j && c == k)
					return idx;
				idx++;
			}
	return -1;
}

static void test_poly_order(void **state)
{
	(void)state;
	/* The manual's quartic torus (major sqrt(40), minor sqrt(12)) has its
	 * coefficients at these 1-based places. */
	assert_int_equal(pov_index(4, 4, 0, 0), 0);
	assert_int_equal(pov_index(4, 2, 2, 0), 4);
	assert_int_equal(pov_index(4, 2, 0, 2), 7);
	assert_int_equal(pov_index(4, 2, 0, 0), 9);
	assert_int_equal(pov_index(4, 0, 4, 0), 20);
	assert_int_equal(pov_index(4, 0, 2, 2), 23);
	assert_int_equal(pov_index(4, 0, 2, 0), 25);
	assert_int_equal(pov_index(4, 0, 0, 4), 30);
	assert_int_equal(pov_index(4, 0, 0, 2), 32);
	assert_int_equal(pov_index(4, 0, 0, 0), 34);
	/* The manual's table: A2 of a 2nd order poly is xy, A120 of 7th is 1. */
	assert_int_equal(pov_index(2, 1, 1, 0), 1);
	assert_int_equal(pov_index(7, 0, 0, 0), 119);
}

static struct object *sphere_poly(bool sturm)
{
	double c[10] = {0};
	c[pov_index(2, 2, 0, 0)] = 1;
	c[pov_index(2, 0, 2, 0)] = 1;
	c[pov_index(2, 0, 0, 2)] = 1;
	c[pov_index(2, 0, 0, 0)] = -1;
	return poly_new(2, c, sturm, nopos);
}

static void test_poly_sphere(void **state)
{
	(void)state;
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *P = sphere_poly(sturm);
		assert_non_null(P);
		vec3 org = v3(0, 0, -5), dz = v3(0, 0, 1);
		struct hit h = must_hit(P, org, dz, 0);
		assert_near(h.t, 4, 1e-15);
		assert_vec_near(hit_normal(P, org, dz, &h), 0, 0, -1, 1e-15);
		double t[8];
		assert_int_equal(all_hits(P, org, dz, 0, t), 2);
		assert_near(t[1], 6, 1e-15);
		/* From inside, and a non-unit diagonal direction. */
		h = must_hit(P, v3(0, 0, 0), v3(2, 2, 1), 0);
		assert_near(h.t, 1.0 / 3, 1e-15);
		assert_false(hits(P, v3(0, 1.01, -5), dz, 0, INFINITY));
		assert_false(hits(P, org, v3(0, 0, -1), 0, INFINITY));
		/* Starting far away. */
		h = must_hit(P, v3(0, 0, -1e6), dz, 0);
		assert_near(h.t, 1e6 - 1, 1e-15 * 1e6);
		object_free(P);
	}
}

/* The manual's quartic torus agrees with the torus primitive. */
static void test_poly_quartic_torus(void **state)
{
	(void)state;
	static const double q[35] = {1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0,
	                             0, 0, 1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784};
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *P = poly_new(4, q, sturm, nopos), *T = torus_new(sqrt(40), sqrt(12), false, nopos);
		unsigned seed = 99;
		int nhit = 0;
		for (int i = 0; i < 500; i++) {
			double u[6];
			for (int k = 0; k < 6; k++) {
				seed = seed * 1103515245u + 12345u;
				u[k] = (seed >> 8) / 16777216.0 - 0.5;
			}
			vec3 org = v3(40 * u[0], 40 * u[1], -30);
			vec3 dir = v3_sub(v3(12 * u[2], 6 * u[3], 12 * u[4]), org);
			double tp[8], tt[8];
			struct ray ray = mkray(org, dir);
			struct hit hp[8], ht[8];
			int np = P->ops->all_hits(P, &ray, 0, INFINITY, hp, 8);
			int nt = T->ops->all_hits(T, &ray, 0, INFINITY, ht, 8);
			assert_int_equal(np, nt);
			for (int k = 0; k < np; k++) {
				tp[k] = hp[k].t;
				tt[k] = ht[k].t;
				assert_near(tp[k], tt[k], 1e-11 * tt[k]);
				vec3 p = v3_madd(org, dir, tt[k]);
				vec3 n0 = v3_norm(P->ops->normal(P, p, &hp[k]));
				vec3 n1 = v3_norm(T->ops->normal(T, p, &ht[k]));
				assert_vec_near(n0, n1.x, n1.y, n1.z, 1e-9);
			}
			nhit += np > 0;
		}
		assert_true(nhit > 100);
		object_free(P);
		object_free(T);
	}
}

static void test_poly_cubic(void **state)
{
	(void)state;
	/* x^3 + y^3 + z^3 = 1. */
	double c[20] = {0};
	c[pov_index(3, 3, 0, 0)] = 1;
	c[pov_index(3, 0, 3, 0)] = 1;
	c[pov_index(3, 0, 0, 3)] = 1;
	c[pov_index(3, 0, 0, 0)] = -1;
	assert_int_equal(pov_index(3, 0, 3, 0), 10);
	assert_int_equal(pov_index(3, 0, 0, 3), 16);
	assert_int_equal(pov_index(3, 0, 0, 0), 19);
	for (int sturm = 0; sturm < 2; sturm++) {
		struct object *P = poly_new(3, c, sturm, nopos);
		struct hit h = must_hit(P, v3(-5, 0, 0), v3(1, 0, 0), 0);
		assert_near(h.t, 6, 1e-15);
		h = must_hit(P, v3(-5, 0.5, 0), v3(1, 0, 0), 0);
		assert_near(h.t, 5 + cbrt(0.875), 1e-15);
		/* Gradient (3x^2, 3y^2, 3z^2). */
		vec3 n = hit_normal(P, v3(-5, 0.5, 0), v3(1, 0, 0), &h);
		double x = cbrt(0.875), l = hypot(x * x, 0.25);
		assert_vec_near(n, x * x / l, 0.25 / l, 0, 1e-15);
		/* Along (1,-1,0) the cubic terms cancel: from (0.5,0,0) the
		 * equation is 1.5 t^2 + 0.75 t - 0.875 = 0. */
		h = must_hit(P, v3(0.5, 0, 0), v3(1, -1, 0), 0);
		assert_near(h.t, (-0.75 + sqrt(5.8125)) / 3, 1e-15);
		object_free(P);
	}
}

static void test_poly_high_order(void **state)
{
	(void)state;
	/* Order 6: x^6 + y^6 + z^6 = 1, a rounded cube. */
	double c6[84] = {0};
	c6[pov_index(6, 6, 0, 0)] = 1;
	c6[pov_index(6, 0, 6, 0)] = 1;
	c6[pov_index(6, 0, 0, 6)] = 1;
	c6[pov_index(6, 0, 0, 0)] = -1;
	struct object *P = poly_new(6, c6, false, nopos);
	struct hit h = must_hit(P, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 1e-14);
	h = must_hit(P, v3(0, 0, 0), v3(1, 1, 1), 0);
	assert_near(h.t, pow(3, -1.0 / 6), 1e-15);
	assert_vec_near(hit_normal(P, v3(0, 0, 0), v3(1, 1, 1), &h), sqrt(1 / 3.0), sqrt(1 / 3.0), sqrt(1 / 3.0), 1e-15);
	assert_true(object_inside(P, v3(0.8, 0.8, 0)));
	assert_false(object_inside(P, v3(0.9, 0.9, 0)));
	assert_false(object_inside(P, v3(1.01, 0, 0)));
	double t[8];
	assert_int_equal(all_hits(P, v3(-5, 0.5, 0.5), v3(1, 0, 0), 0, t), 2);
	assert_near(t[0], 5 - pow(1 - 2 * pow(0.5, 6), 1.0 / 6), 1e-14);
	object_free(P);
	/* Order 7: x^7 - y + 2 x^5 z^2 - 3 x y z, which is y = x^7 in the plane
	 * z = 0. */
	double c7[120] = {0};
	c7[pov_index(7, 7, 0, 0)] = 1;
	c7[pov_index(7, 0, 1, 0)] = -1;
	c7[pov_index(7, 5, 0, 2)] = 2;
	c7[pov_index(7, 1, 1, 1)] = -3;
	P = poly_new(7, c7, true, nopos);
	h = must_hit(P, v3(0.5, -5, 0), v3(0, 1, 0), 0);
	assert_near(h.t, 5 + pow(0.5, 7), 1e-15);
	/* Gradient (7x^6 + 10x^4z^2 - 3yz, -1 - 3xz, 4x^5z - 3xy) at z = 0. */
	vec3 n = hit_normal(P, v3(0.5, -5, 0), v3(0, 1, 0), &h);
	double gx = 7 * pow(0.5, 6), gz = -3 * 0.5 * pow(0.5, 7), l = sqrt(gx * gx + 1 + gz * gz);
	assert_vec_near(n, gx / l, -1 / l, gz / l, 1e-15);
	/* Along x at y = 1: x^7 = 1. */
	h = must_hit(P, v3(-3, 1, 0), v3(1, 0, 0), 0);
	assert_near(h.t, 4, 1e-14);
	object_free(P);
	assert_null(poly_new(1, c7, false, nopos));
	assert_null(poly_new(8, c7, false, nopos));
}

static void test_poly_inside_normal_bounds(void **state)
{
	(void)state;
	struct object *P = sphere_poly(false);
	assert_true(object_inside(P, v3(0, 0, 0)));
	assert_false(object_inside(P, v3(2, 0, 0)));
	/* POV-Ray (measured with its inside()): f < 1e-4 is inside, so the
	 * surface and a thin shell outside it count. */
	assert_true(object_inside(P, v3(1, 0, 0)));
	assert_true(object_inside(P, v3(sqrt(1 + 0.5e-4), 0, 0)));
	assert_false(object_inside(P, v3(sqrt(1 + 2e-4), 0, 0)));
	assert_vec_near(v3_norm(P->ops->normal(P, v3(0, 1, 0), NULL)), 0, 1, 0, 0);
	/* A singular point gives a usable normal, not a zero vector. */
	vec3 n = P->ops->normal(P, v3(0, 0, 0), NULL);
	assert_true(v3_len(n) > 0);
	struct aabb b = P->ops->bounds(P);
	assert_false(aabb_is_finite(b));
	assert_true(b.lo.x == -INFINITY && b.hi.z == INFINITY);
	assert_null(P->ops->uv);
	/* Copy, then transform the copy: scaled by 2, hit at t = 3. */
	struct object *Q = object_copy(P);
	transform(Q, xform_scale(v3(2, 2, 2)));
	struct hit h = must_hit(Q, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 3, 1e-15);
	assert_vec_near(hit_normal(Q, v3(0, 0, -5), v3(0, 0, 1), &h), 0, 0, -1, 1e-15);
	h = must_hit(P, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 4, 1e-15);
	object_free(P);
	object_free(Q);
}

/* A paraboloid y = x^2 + z^2 along its axis (the t^2 term vanishes) and a
 * cylinder x^2 + y^2 = 1 along its axis (no root at all). */
static void test_poly_degenerate_rays(void **state)
{
	(void)state;
	double c[10] = {0};
	c[pov_index(2, 2, 0, 0)] = 1;
	c[pov_index(2, 0, 0, 2)] = 1;
	c[pov_index(2, 0, 1, 0)] = -1;
	struct object *P = poly_new(2, c, false, nopos);
	struct hit h = must_hit(P, v3(0, -5, 0), v3(0, 1, 0), 0);
	assert_near(h.t, 5, 1e-15);
	assert_vec_near(hit_normal(P, v3(0, -5, 0), v3(0, 1, 0), &h), 0, -1, 0, 0);
	h = must_hit(P, v3(1, -5, 0), v3(0, 1, 0), 0);
	assert_near(h.t, 6, 1e-15);
	object_free(P);
	double d[10] = {0};
	d[pov_index(2, 2, 0, 0)] = 1;
	d[pov_index(2, 0, 2, 0)] = 1;
	d[pov_index(2, 0, 0, 0)] = -1;
	P = poly_new(2, d, true, nopos);
	assert_false(hits(P, v3(0, 0, -5), v3(0, 0, 1), 0, INFINITY));
	assert_false(hits(P, v3(0.5, 0.5, -5), v3(0, 0, 3), 0, INFINITY));
	assert_false(hits(P, v3(0, 0, -5), v3(0, 0, 0), 0, INFINITY));
	h = must_hit(P, v3(0, 0, -5), v3(1, 0, 1), 0);
	assert_near(h.t, 1, 1e-15);
	object_free(P);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cubic_basic),
		cmocka_unit_test(test_cubic_multiple),
		cmocka_unit_test(test_cubic_wide_range),
		cmocka_unit_test(test_quartic_basic),
		cmocka_unit_test(test_quartic_multiple),
		cmocka_unit_test(test_quartic_wide_range),
		cmocka_unit_test(test_quartic_ill_conditioned),
		cmocka_unit_test(test_poly_interval),
		cmocka_unit_test(test_poly_high_degree),
		cmocka_unit_test(test_poly_degenerate),
		cmocka_unit_test(test_poly_closed_vs_sturm),
		cmocka_unit_test(test_torus_hits),
		cmocka_unit_test(test_torus_inside_start),
		cmocka_unit_test(test_torus_tangent),
		cmocka_unit_test(test_torus_thin_far),
		cmocka_unit_test(test_torus_thin_general),
		cmocka_unit_test(test_torus_sturm_regression),
		cmocka_unit_test(test_torus_normal_inside_bounds),
		cmocka_unit_test(test_torus_uv),
		cmocka_unit_test(test_torus_transformed),
		cmocka_unit_test(test_torus_degenerate),
		cmocka_unit_test(test_poly_order),
		cmocka_unit_test(test_poly_sphere),
		cmocka_unit_test(test_poly_quartic_torus),
		cmocka_unit_test(test_poly_cubic),
		cmocka_unit_test(test_poly_high_order),
		cmocka_unit_test(test_poly_inside_normal_bounds),
		cmocka_unit_test(test_poly_degenerate_rays),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

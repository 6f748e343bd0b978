/* test_uv.c: unit tests for the uv operation of the primitives that have
 * POV-Ray uv coordinates (sphere and box; torus and meshes are covered by
 * their own tests). The expected values are the analytic ones; each was
 * also measured in POV-Ray 3.7 (`uv_mapping` with `gradient x` and
 * `gradient y` pigments read back from 16-bit linear PNGs, coarse and
 * fine (frequency 64) renders combined, about 1e-7 precise) and the
 * measurement is quoted in the comment beside it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/shapes.h"
#include "scene/object.h"

#include <math.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};
static const double PI = 3.14159265358979323846;

/* uv of object o at object-space point p for hit h, checked to succeed and
 * to lie in the unit square. */
static void uv_at(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	assert_non_null(o->ops->uv);
	assert_true(o->ops->uv(o, p, h, uv));
	assert_true(uv[0] >= 0 && uv[0] < 1.0 + 1e-15);
	assert_true(uv[1] >= 0 && uv[1] <= 1);
}

#define assert_uv(o, p, h, eu, ev, tol)                                   \
	do {                                                              \
		double uv_[2];                                            \
		uv_at((o), (p), (h), uv_);                                \
		assert_near(uv_[0], (eu), (tol));                         \
		assert_near(uv_[1], (ev), (tol));                         \
	} while (0)

/* uv where the world ray org + t dir first hits o: the hit point carried
 * into object space, as the texture code will do. */
static void uv_of_ray(const struct object *o, vec3 org, vec3 dir, double uv[2])
{
	struct hit h = must_hit(o, org, dir, 0);
	vec3 p = v3_madd(org, dir, h.t);
	if (o->has_xf)
		p = mat_point(&o->xf.inv, p);
	uv_at(h.obj, p, &h, uv);
}

/* ---- sphere ---- */

/* sphere { <1,2,3>, 2 }: u = atan2(z,x)/2pi in [0,1), v = 1/2 + latitude/pi,
 * relative to the centre. */
static void test_sphere_points(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(1, 2, 3), 2, nopos);
	double r3 = 2 / sqrt(3.0), r2 = sqrt(2.0);
	/* The four horizontal directions (POV: 0.750000 0.500000, 0.250000
	 * 0.500000, 0.500000 0.500000); u = 0 on +x. */
	assert_uv(s, v3(1, 2, 1), NULL, 0.75, 0.5, 1e-15);
	assert_uv(s, v3(1, 2, 5), NULL, 0.25, 0.5, 1e-15);
	assert_uv(s, v3(-1, 2, 3), NULL, 0.5, 0.5, 1e-15);
	assert_uv(s, v3(3, 2, 3), NULL, 0, 0.5, 1e-15);
	/* Along <1,1,1> (POV: 0.125000 0.695913). */
	assert_uv(s, v3(1 + r3, 2 + r3, 3 + r3), NULL, 0.125, 0.5 + asin(1 / sqrt(3.0)) / PI, 1e-15);
	assert_near(0.5 + asin(1 / sqrt(3.0)) / PI, 0.695913, 1e-6);
	/* Along <-1,-1,-sqrt2>: latitude -30 degrees (POV: 0.652043 0.333333). */
	assert_uv(s, v3(0, 1, 3 - r2), NULL, 1 + atan2(-r2, -1) / (2 * PI), 1.0 / 3, 1e-15);
	assert_near(1 + atan2(-r2, -1) / (2 * PI), 0.652043, 1e-6);
	/* Along <1,2,-2>/3 (POV: 0.823792 0.732280). */
	assert_uv(s, v3(1 + 2.0 / 3, 2 + 4.0 / 3, 3 - 4.0 / 3), NULL, 1 + atan2(-2, 1) / (2 * PI),
	          0.5 + asin(2.0 / 3) / PI, 1e-15);
	assert_near(1 + atan2(-2, 1) / (2 * PI), 0.823792, 1e-6);
	assert_near(0.5 + asin(2.0 / 3) / PI, 0.732280, 1e-6);
	/* The poles: v = 1 and 0, u = 0 (POV: 0.000000 1.000000, 0.000000 0.000000). */
	assert_uv(s, v3(1, 4, 3), NULL, 0, 1, 0);
	assert_uv(s, v3(1, 0, 3), NULL, 0, 0, 0);
	object_free(s);
}

/* u is continuous across the seam modulo 1: just below it u is near 1,
 * just above near 0, and it never reaches 1. */
static void test_sphere_seam(void **state)
{
	(void)state;
	struct object *s = sphere_new(v3(1, 2, 3), 2, nopos);
	double e = 0.01;
	/* POV: 0.998409 0.500000 and 0.001591 0.500000. */
	assert_uv(s, v3(1 + 2 * cos(e), 2, 3 - 2 * sin(e)), NULL, 1 - e / (2 * PI), 0.5, 1e-15);
	assert_uv(s, v3(1 + 2 * cos(e), 2, 3 + 2 * sin(e)), NULL, e / (2 * PI), 0.5, 1e-15);
	assert_near(1 - e / (2 * PI), 0.998409, 1e-6);
	/* So close below the seam that u + 1 rounds to 1: reported as 0. */
	double uv[2];
	uv_at(s, v3(3, 2, 3 - 1e-300), NULL, uv);
	assert_true(uv[0] < 1);
	assert_true(uv[0] == 0 || uv[0] > 0.999999);
	uv_at(s, v3(3, 2, 3 - 1e-18), NULL, uv);
	assert_true(uv[0] < 1);
	object_free(s);
}

/* uv depends only on the direction from the centre: any radius, a point
 * off the surface, and the degenerate sphere all give finite values. */
static void test_sphere_scale_and_degenerate(void **state)
{
	(void)state;
	struct object *big = sphere_new(v3(0, 0, 0), 1e6, nopos);
	struct object *tiny = sphere_new(v3(0, 0, 0), 1e-9, nopos);
	assert_uv(big, v3(0, 5e5, -5e5 * sqrt(3.0)), NULL, 0.75, 0.5 + 1.0 / 6, 1e-15);
	assert_uv(tiny, v3(0, 5e-10, -5e-10 * sqrt(3.0)), NULL, 0.75, 0.5 + 1.0 / 6, 1e-15);
	struct object *zero = sphere_new(v3(1, 1, 1), 0, nopos);
	assert_uv(zero, v3(1, 1, 1), NULL, 0, 0.5, 0);
	object_free(big);
	object_free(tiny);
	object_free(zero);
}

/* Through intersect, with and without a transform: uv follows the object
 * (POV-Ray computes it in object space). */
static void test_sphere_ray(void **state)
{
	(void)state;
	double uv[2];
	struct object *s = sphere_new(v3(0, 0, 0), 1, nopos);
	/* From the front along +z: the hit <0,0,-1> (POV: 0.750000 0.500000). */
	uv_of_ray(s, v3(0, 0, -5), v3(0, 0, 1), uv);
	assert_near(uv[0], 0.75, 1e-15);
	assert_near(uv[1], 0.5, 1e-15);
	/* sphere { <0.5,0,0>, 1 scale <2,1,1> rotate y*90 translate y }: the
	 * ray from <0.3,1.4,-10> along +z hits at world <0.3,1.4,-2.73205>,
	 * object <1.36603,0.4,0.3> (POV: 0.053074 0.630990). */
	object_free(s);
	s = sphere_new(v3(0.5, 0, 0), 1, nopos);
	transform(s, xform_scale(v3(2, 1, 1)));
	transform(s, xform_rotate(v3(0, 90, 0)));
	transform(s, xform_translate(v3(0, 1, 0)));
	uv_of_ray(s, v3(0.3, 1.4, -10), v3(0, 0, 1), uv);
	double dx = sqrt(0.75), dy = 0.4, dz = 0.3; /* object point minus centre */
	assert_near(uv[0], atan2(dz, dx) / (2 * PI), 1e-12);
	assert_near(uv[1], 0.5 + atan2(dy, hypot(dx, dz)) / PI, 1e-12);
	assert_near(uv[0], 0.053074, 1e-6);
	assert_near(uv[1], 0.630990, 1e-6);
	object_free(s);
}

/* ---- box ---- */

/* box { <-1,-0.5,-2>, <2,1,0.5> }: sizes 3, 1.5, 2.5. Each face fills a
 * 1/4 x 1/3 cell of the cross (see box.c), whatever the proportions. */
static void test_box_faces(void **state)
{
	(void)state;
	struct object *b = box_new(v3(2, 1, 0.5), v3(-1, -0.5, -2), nopos);
	struct hit h = {.part = 0};
	/* -x at y' = 0.6, z' = 0.4: u = z'/4, v = (1 + y')/3 (POV: 0.100000 0.533333). */
	h.part = 0;
	assert_uv(b, v3(-1, 0.4, -1), &h, 0.1, 1.6 / 3, 1e-15);
	/* +x at y' = 0.2, z' = 0.8: u = 3/4 - z'/4 (POV: 0.550000 0.400000). */
	h.part = 1;
	assert_uv(b, v3(2, -0.2, 0), &h, 0.55, 1.2 / 3, 1e-15);
	/* -y at x' = 0.5, z' = 0.2: u = 1/4 + x'/4, v = z'/3 (POV: 0.375000 0.066667). */
	h.part = 2;
	assert_uv(b, v3(0.5, -0.5, -1.5), &h, 0.375, 0.2 / 3, 1e-15);
	/* +y at x' = 0.2, z' = 0.9: v = 1 - z'/3 (POV: 0.300000 0.700000). */
	h.part = 3;
	assert_uv(b, v3(-0.4, 1, 0.25), &h, 0.3, 0.7, 1e-15);
	/* -z at x' = 0.7, y' = 0.8: u = 1 - x'/4 (POV: 0.825000 0.600000). */
	h.part = 4;
	assert_uv(b, v3(1.1, 0.7, -2), &h, 0.825, 0.6, 1e-15);
	/* +z at x' = 0.4, y' = 0.1: u = 1/4 + x'/4 (POV: 0.350000 0.366667). */
	h.part = 5;
	assert_uv(b, v3(0.2, -0.35, 0.5), &h, 0.35, 1.1 / 3, 1e-15);
	/* Points POV-Ray was probed at from random directions:
	 * +x <2,0.9100962,-1.39055543> (POV: 0.689055 0.646688),
	 * -y <0.49155828,-0.5,-1.84846344> (POV: 0.374296 0.020205),
	 * -z <0.02219813,-0.22223037,-2> (POV: 0.914817 0.395060). */
	h.part = 1;
	assert_uv(b, v3(2, 0.9100962, -1.39055543), &h, 0.75 - (-1.39055543 + 2) / 2.5 / 4,
	          (1 + (0.9100962 + 0.5) / 1.5) / 3, 1e-15);
	assert_near(0.75 - (-1.39055543 + 2) / 2.5 / 4, 0.689055, 1e-6);
	assert_near((1 + (0.9100962 + 0.5) / 1.5) / 3, 0.646688, 1e-6);
	h.part = 2;
	assert_uv(b, v3(0.49155828, -0.5, -1.84846344), &h, 0.25 + (0.49155828 + 1) / 3 / 4,
	          (-1.84846344 + 2) / 2.5 / 3, 1e-15);
	assert_near(0.25 + (0.49155828 + 1) / 3 / 4, 0.374296, 1e-6);
	assert_near((-1.84846344 + 2) / 2.5 / 3, 0.020205, 1e-6);
	h.part = 4;
	assert_uv(b, v3(0.02219813, -0.22223037, -2), &h, 1 - (0.02219813 + 1) / 3 / 4,
	          (1 + (-0.22223037 + 0.5) / 1.5) / 3, 1e-15);
	assert_near(1 - (0.02219813 + 1) / 3 / 4, 0.914817, 1e-6);
	assert_near((1 + (-0.22223037 + 0.5) / 1.5) / 3, 0.395060, 1e-6);
	object_free(b);
}

/* The cell corners: each face's corners land on the grid lines of the
 * cross, so neighbouring faces meet edge to edge where the cross folds. */
static void test_box_corners(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -1, -1), v3(1, 1, 1), nopos);
	struct hit h = {.part = 5};
	/* +z: corner <-1,-1,1> at the cell's lower left, <1,1,1> upper right. */
	assert_uv(b, v3(-1, -1, 1), &h, 0.25, 1.0 / 3, 1e-15);
	assert_uv(b, v3(1, 1, 1), &h, 0.5, 2.0 / 3, 1e-15);
	/* +x shares the edge x = 1, z = 1 with +z at u = 1/2. */
	h.part = 1;
	assert_uv(b, v3(1, 0, 1), &h, 0.5, 0.5, 1e-15);
	assert_uv(b, v3(1, 0, -1), &h, 0.75, 0.5, 1e-15);
	/* -z continues from +x at u = 3/4 and ends at u = 1 on x = -1. */
	h.part = 4;
	assert_uv(b, v3(1, 0, -1), &h, 0.75, 0.5, 1e-15);
	assert_uv(b, v3(-1, 0, -1), &h, 1, 0.5, 1e-15);
	/* -x starts at u = 0 on z = -1 and meets +z at u = 1/4. */
	h.part = 0;
	assert_uv(b, v3(-1, 0, -1), &h, 0, 0.5, 1e-15);
	assert_uv(b, v3(-1, 0, 1), &h, 0.25, 0.5, 1e-15);
	/* +y meets +z along z = 1 at v = 2/3, -y meets it at v = 1/3. */
	h.part = 3;
	assert_uv(b, v3(0, 1, 1), &h, 0.375, 2.0 / 3, 1e-15);
	assert_uv(b, v3(0, 1, -1), &h, 0.375, 1, 1e-15);
	h.part = 2;
	assert_uv(b, v3(0, -1, 1), &h, 0.375, 1.0 / 3, 1e-15);
	assert_uv(b, v3(0, -1, -1), &h, 0.375, 0, 1e-15);
	object_free(b);
}

/* Without a hit record (or with an unknown part) the face nearest p is
 * used; a point a rounding error off its face stays inside the cell. */
static void test_box_no_hit_and_clamp(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -0.5, -2), v3(2, 1, 0.5), nopos);
	assert_uv(b, v3(-1, 0.4, -1), NULL, 0.1, 1.6 / 3, 1e-15);
	assert_uv(b, v3(1.1, 0.7, -2), NULL, 0.825, 0.6, 1e-15);
	struct hit h = {.part = -1};
	assert_uv(b, v3(-0.4, 1, 0.25), &h, 0.3, 0.7, 1e-15);
	/* On +z, just beyond the x and y ranges: clamped to the cell's corner
	 * instead of spilling into the -z or +y cells. */
	h.part = 5;
	assert_uv(b, v3(-1 - 1e-12, 1 + 1e-12, 0.5 + 1e-13), &h, 0.25, 2.0 / 3, 0);
	h.part = 4;
	assert_uv(b, v3(-1 - 1e-12, -0.5 - 1e-12, -2), &h, 1, 1.0 / 3, 0);
	object_free(b);
}

/* Flat boxes: the flat axis's own faces are the only ones a ray can hit;
 * the other coordinates still normalise, and nothing becomes NaN. (For a
 * flat box POV-Ray labels the hit with the face on the far side of the
 * ray; lucent's intersect reports the near one, so the cell can differ.) */
static void test_box_flat(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -0.5, 0.1), v3(0.8, 0.9, 0.1), nopos);
	double uv[2];
	uv_of_ray(b, v3(0.35, 0.2, -5), v3(0, 0, 1), uv);
	/* x' = 0.75, y' = 0.5: a z face, u = 1/4 + x'/4 on +z or 1 - x'/4 on -z. */
	assert_true(fabs(uv[0] - 0.4375) < 1e-15 || fabs(uv[0] - 0.8125) < 1e-15);
	assert_near(uv[1], 0.5, 1e-15);
	/* The other faces' formulas meet a zero size: finite, in the cell. */
	struct hit h = {.part = 1};
	assert_uv(b, v3(0.8, 0.2, 0.1), &h, 0.75, 0.5, 1e-15);
	struct object *pt = box_new(v3(1, 1, 1), v3(1, 1, 1), nopos);
	for (int f = 0; f < 6; f++) {
		h.part = f;
		uv_at(pt, v3(1, 1, 1), &h, uv);
		assert_true(isfinite(uv[0]) && isfinite(uv[1]));
	}
	object_free(b);
	object_free(pt);
}

/* Through intersect: every face is found from outside, and a transformed
 * box maps in its own object space. */
static void test_box_ray(void **state)
{
	(void)state;
	struct object *b = box_new(v3(-1, -0.5, -2), v3(2, 1, 0.5), nopos);
	static const struct { vec3 org, dir; double u, v; } rays[] = {
		{{-5, 0.4, -1}, {1, 0, 0}, 0.1, 1.6 / 3},                 /* -x */
		{{5, -0.2, 0}, {-1, 0, 0}, 0.55, 1.2 / 3},                /* +x */
		{{0.5, -5, -1.5}, {0, 1, 0}, 0.375, 0.2 / 3},             /* -y */
		{{-0.4, 5, 0.25}, {0, -1, 0}, 0.3, 0.7},                  /* +y */
		{{1.1, 0.7, -5}, {0, 0, 1}, 0.825, 0.6},                  /* -z */
		{{0.2, -0.35, 5}, {0, 0, -1}, 0.35, 1.1 / 3},             /* +z */
		{{-5, 0.4 - 1.2, -1 - 0.8}, {4, 1.2, 0.8}, 0.1, 1.6 / 3}, /* -x, oblique */
	};
	double uv[2];
	for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
		uv_of_ray(b, rays[i].org, rays[i].dir, uv);
		assert_near(uv[0], rays[i].u, 1e-15);
		assert_near(uv[1], rays[i].v, 1e-15);
	}
	/* box { <-1,-0.5,-2>, <2,1,0.5> rotate x*30 scale 0.5 }: the ray from
	 * <0.2,0.1,-10> along +z hits the -y face at world
	 * <0.2,0.1,-0.673205>, object <0.4,-0.5,-(0.4 + sqrt3/2)>
	 * (POV: 0.366667 0.097863). */
	transform(b, xform_rotate(v3(30, 0, 0)));
	transform(b, xform_scale(v3(0.5, 0.5, 0.5)));
	struct hit h = must_hit(b, v3(0.2, 0.1, -10), v3(0, 0, 1), 0);
	assert_int_equal(h.part, 2);
	uv_of_ray(b, v3(0.2, 0.1, -10), v3(0, 0, 1), uv);
	assert_near(uv[0], 0.25 + 1.4 / 3 / 4, 1e-15);
	assert_near(uv[1], (2 - 0.4 - sqrt(0.75)) / 2.5 / 3, 1e-14);
	assert_near(uv[0], 0.366667, 1e-6);
	assert_near(uv[1], 0.097863, 1e-6);
	object_free(b);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_sphere_points),
		cmocka_unit_test(test_sphere_seam),
		cmocka_unit_test(test_sphere_scale_and_degenerate),
		cmocka_unit_test(test_sphere_ray),
		cmocka_unit_test(test_box_faces),
		cmocka_unit_test(test_box_corners),
		cmocka_unit_test(test_box_no_hit_and_clamp),
		cmocka_unit_test(test_box_flat),
		cmocka_unit_test(test_box_ray),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_math.c: unit tests for the math layer: vectors and boxes
 * (src/math/vec.h), 4x4 affine transforms under POV-Ray's conventions
 * (src/math/mat.h), the deterministic hash (src/math/hash.h) and the
 * quadratic solver (src/geom/solve.h). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/solve.h"
#include "math/hash.h"
#include "math/mat.h"
#include "math/vec.h"

#include <math.h>
#include <string.h>

#include "testutil.h"

/* Exact comparison, for results the code promises to get bit for bit. */
#define assert_vec_exact(v, ex, ey, ez) assert_vec_near(v, ex, ey, ez, 0.0)

static void assert_mat_near(const mat4 *a, const mat4 *b, double tol)
{
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			if (!(fabs(a->m[i][j] - b->m[i][j]) <= tol))
				fail_msg("m[%d][%d] = %.17g, expected %.17g", i, j, a->m[i][j], b->m[i][j]);
}

/* A matrix from 12 numbers given row by row (the bottom row is 0 0 0 1). */
static mat4 mat_rows(const double r[12])
{
	mat4 m = mat_identity();
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++)
			m.m[i][j] = r[i * 4 + j];
	return m;
}

/* ---- vec.h ---- */

static void test_vec_arith(void **state)
{
	(void)state;
	vec3 a = v3(1, 2, 3), b = v3(-4, 0.5, 2);
	assert_vec_exact(v3_add(a, b), -3, 2.5, 5);
	assert_vec_exact(v3_sub(a, b), 5, 1.5, 1);
	assert_vec_exact(v3_mul(a, b), -4, 1, 6);
	assert_vec_exact(v3_scale(a, -2), -2, -4, -6);
	assert_vec_exact(v3_neg(b), 4, -0.5, -2);
	assert_near(v3_dot(a, b), -4 + 1 + 6, 0);
	assert_vec_exact(v3_madd(a, b, 2), -7, 3, 7);
	assert_vec_exact(v3_min(a, b), -4, 0.5, 2);
	assert_vec_exact(v3_max(a, b), 1, 2, 3);
	assert_near(v3_get(a, 0), 1, 0);
	assert_near(v3_get(a, 1), 2, 0);
	assert_near(v3_get(a, 2), 3, 0);
	assert_near(v3_maxabs(v3(1, -7, 3)), 7, 0);
	assert_near(v3_maxabs(v3(-9, 2, 3)), 9, 0);
	assert_near(v3_maxabs(v3(0, 2, -3)), 3, 0);
}

static void test_vec_cross_len_norm(void **state)
{
	(void)state;
	/* The cross product is the same formula whatever the handedness. */
	assert_vec_exact(v3_cross(v3(1, 0, 0), v3(0, 1, 0)), 0, 0, 1);
	assert_vec_exact(v3_cross(v3(0, 1, 0), v3(0, 0, 1)), 1, 0, 0);
	assert_vec_exact(v3_cross(v3(0, 0, 1), v3(1, 0, 0)), 0, 1, 0);
	assert_vec_exact(v3_cross(v3(1, 2, 3), v3(4, 5, 6)), -3, 6, -3);
	assert_near(v3_len(v3(3, 4, 12)), 13, 0);
	assert_vec_near(v3_norm(v3(3, 4, 12)), 3.0 / 13, 4.0 / 13, 12.0 / 13, 1e-16);
	assert_near(v3_len(v3_norm(v3(1e-150, 3e-150, -2e-150))), 1, 1e-15);
	/* A zero vector stays zero, never NaN. */
	vec3 z = v3_norm(v3(0, 0, 0));
	assert_vec_exact(z, 0, 0, 0);
}

static void test_vec_reflect(void **state)
{
	(void)state;
	assert_vec_exact(v3_reflect(v3(1, -1, 0), v3(0, 1, 0)), 1, 1, 0);
	assert_vec_exact(v3_reflect(v3(0, 0, 2), v3(0, 0, -1)), 0, 0, -2);
	/* A direction in the surface is unchanged. */
	assert_vec_exact(v3_reflect(v3(1, 0, 5), v3(0, 1, 0)), 1, 0, 5);
}

static void test_aabb(void **state)
{
	(void)state;
	struct aabb e = aabb_empty();
	assert_false(aabb_is_finite(e));
	assert_near(aabb_area(e), 0, 0);
	struct aabb b = aabb_add_point(e, v3(1, 2, 3));
	assert_vec_exact(b.lo, 1, 2, 3);
	assert_vec_exact(b.hi, 1, 2, 3);
	b = aabb_add_point(b, v3(-1, 4, 0));
	assert_vec_exact(b.lo, -1, 2, 0);
	assert_vec_exact(b.hi, 1, 4, 3);
	assert_true(aabb_is_finite(b));
	assert_vec_exact(aabb_center(b), 0, 3, 1.5);
	/* 2 x 2 x 3 box: 2 * (4 + 6 + 6). */
	assert_near(aabb_area(b), 32, 0);
	struct aabb c = {v3(5, -5, 1), v3(6, -4, 2)};
	struct aabb u = aabb_union(b, c);
	assert_vec_exact(u.lo, -1, -5, 0);
	assert_vec_exact(u.hi, 6, 4, 3);
	/* The empty box is the identity of union. */
	u = aabb_union(e, c);
	assert_vec_exact(u.lo, 5, -5, 1);
	assert_vec_exact(u.hi, 6, -4, 2);
	struct aabb inf = {v3(-INFINITY, 0, 0), v3(1, 1, 1)};
	assert_false(aabb_is_finite(inf));
}

/* ---- mat.h: matrices ---- */

static void test_mat_identity(void **state)
{
	(void)state;
	mat4 i = mat_identity();
	assert_true(mat_is_identity(&i));
	for (int r = 0; r < 4; r++)
		for (int c = 0; c < 4; c++)
			assert_near(i.m[r][c], r == c ? 1 : 0, 0);
	i.m[1][3] = 1e-300;
	assert_false(mat_is_identity(&i));
	i = mat_identity();
	i.m[2][2] = 1.0000000000000002;
	assert_false(mat_is_identity(&i));
}

static void test_mat_mul(void **state)
{
	(void)state;
	static const double ra[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
	static const double rb[12] = {0, -1, 0, 2, 1, 0, 0, -3, 0, 0, 2, 1};
	mat4 a = mat_rows(ra), b = mat_rows(rb), id = mat_identity();
	mat4 ai = mat_mul(&a, &id), ia = mat_mul(&id, &a);
	assert_mat_near(&ai, &a, 0);
	assert_mat_near(&ia, &a, 0);
	/* a * b, worked by hand. */
	static const double rab[12] = {2, -1, 6, 3, 6, -5, 14, 7, 10, -9, 22, 11};
	mat4 ab = mat_mul(&a, &b), ex = mat_rows(rab);
	assert_mat_near(&ab, &ex, 0);
	/* b * a differs: apply a first. */
	static const double rba[12] = {-5, -6, -7, -6, 1, 2, 3, 1, 18, 20, 22, 25};
	mat4 ba = mat_mul(&b, &a), ex2 = mat_rows(rba);
	assert_mat_near(&ba, &ex2, 0);
	/* "a * b: apply b first" holds for points. */
	vec3 p = v3(0.5, -2, 3);
	vec3 q1 = mat_point(&ab, p), q2 = mat_point(&a, mat_point(&b, p));
	assert_vec_near(q1, q2.x, q2.y, q2.z, 1e-12);
}

static void test_mat_transpose(void **state)
{
	(void)state;
	static const double ra[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
	mat4 a = mat_rows(ra);
	mat4 t = mat_transpose(&a);
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			assert_near(t.m[i][j], a.m[j][i], 0);
	mat4 tt = mat_transpose(&t);
	assert_mat_near(&tt, &a, 0);
}

static void test_mat_inverse(void **state)
{
	(void)state;
	static const double ra[12] = {2, 1, 0, 3, -1, 3, 1, -2, 0.5, 0, 4, 7};
	mat4 a = mat_rows(ra), inv, id = mat_identity();
	assert_true(mat_inverse(&a, &inv));
	mat4 p1 = mat_mul(&a, &inv), p2 = mat_mul(&inv, &a);
	assert_mat_near(&p1, &id, 1e-14);
	assert_mat_near(&p2, &id, 1e-14);
	/* The bottom row stays 0 0 0 1. */
	assert_near(inv.m[3][0], 0, 0);
	assert_near(inv.m[3][1], 0, 0);
	assert_near(inv.m[3][2], 0, 0);
	assert_near(inv.m[3][3], 1, 0);
	/* A point goes there and back. */
	vec3 p = v3(1.25, -3, 8);
	vec3 q = mat_point(&inv, mat_point(&a, p));
	assert_vec_near(q, 1.25, -3, 8, 1e-13);

	/* Pure translation: the inverse negates it exactly. */
	static const double rt[12] = {1, 0, 0, 5, 0, 1, 0, -6, 0, 0, 1, 0.25};
	mat4 t = mat_rows(rt);
	assert_true(mat_inverse(&t, &inv));
	assert_vec_exact(mat_point(&inv, v3(0, 0, 0)), -5, 6, -0.25);

	/* Very small and very large scales stay invertible. */
	static const double rs[12] = {1e-9, 0, 0, 0, 0, 1e9, 0, 0, 0, 0, 1, 0};
	mat4 s = mat_rows(rs);
	assert_true(mat_inverse(&s, &inv));
	assert_near(inv.m[0][0], 1e9, 1e-6);
	assert_near(inv.m[1][1], 1e-9, 1e-24);
}

static void test_mat_inverse_singular(void **state)
{
	(void)state;
	static const double singular[][12] = {
		{0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3},       /* all zero 3x3 */
		{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0},       /* scale z by 0 */
		{1, 2, 3, 0, 2, 4, 6, 0, 0, 1, 1, 0},       /* row 2 = 2 * row 1 */
		{1, 2, 3, 4, 4, 5, 6, 5, 7, 8, 9, 6},       /* rank 2 */
		{1, 0, 0, 0, 0, NAN, 0, 0, 0, 0, 1, 0},     /* not finite */
		{INFINITY, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0},
	};
	for (size_t k = 0; k < sizeof singular / sizeof singular[0]; k++) {
		mat4 a = mat_rows(singular[k]), inv;
		memset(&inv, 0x55, sizeof inv);
		if (mat_inverse(&a, &inv))
			fail_msg("singular matrix %zu reported invertible", k);
		/* On failure the output is the identity. */
		assert_true(mat_is_identity(&inv));
	}
}

static void test_mat_point_dir(void **state)
{
	(void)state;
	static const double r[12] = {2, 0, 0, 10, 0, 3, 0, 20, 0, 0, 4, 30};
	mat4 m = mat_rows(r);
	assert_vec_exact(mat_point(&m, v3(1, 1, 1)), 12, 23, 34);
	/* Directions ignore the translation. */
	assert_vec_exact(mat_dir(&m, v3(1, 1, 1)), 2, 3, 4);
	assert_vec_exact(mat_point(&m, v3(0, 0, 0)), 10, 20, 30);
	assert_vec_exact(mat_dir(&m, v3(0, 0, 0)), 0, 0, 0);
	/* A general matrix: every entry counts. */
	static const double g[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
	mat4 a = mat_rows(g);
	assert_vec_exact(mat_point(&a, v3(1, -1, 2)), 1 - 2 + 6 + 4, 5 - 6 + 14 + 8, 9 - 10 + 22 + 12);
	assert_vec_exact(mat_dir(&a, v3(1, -1, 2)), 1 - 2 + 6, 5 - 6 + 14, 9 - 10 + 22);
}

static void test_mat_normal(void **state)
{
	(void)state;
	/* Scale x by 2: the plane x + y = 1 becomes x/2 + y = 1, whose normal
	 * is (1/2, 1, 0), not the scaled (2, 1, 0). */
	struct xform s = xform_scale(v3(2, 1, 1));
	vec3 n = mat_normal(&s.inv, v3(1, 1, 0));
	assert_vec_near(n, 0.5, 1, 0, 1e-15);
	/* Under a general matrix the normal stays perpendicular to every
	 * transformed tangent. */
	static const double r[12] = {2, 1, 0, 3, -1, 3, 1, -2, 0.5, 0, 4, 7};
	mat4 m = mat_rows(r), inv;
	assert_true(mat_inverse(&m, &inv));
	vec3 n0 = v3(1, 2, -1);
	vec3 t1 = v3(2, -1, 0), t2 = v3(1, 0, 1); /* both perpendicular to n0 */
	vec3 n1 = mat_normal(&inv, n0);
	assert_near(v3_dot(n1, mat_dir(&m, t1)), 0, 1e-13);
	assert_near(v3_dot(n1, mat_dir(&m, t2)), 0, 1e-13);
	/* It is the inverse transpose: (inv^T n). */
	mat4 it = mat_transpose(&inv);
	vec3 n2 = mat_dir(&it, n0);
	assert_vec_near(n1, n2.x, n2.y, n2.z, 1e-15);
	/* Rotations leave normals as they rotate points. */
	struct xform rz = xform_rotate(v3(0, 0, 90));
	assert_vec_exact(mat_normal(&rz.inv, v3(1, 0, 0)), 0, 1, 0);
}

/* ---- mat.h: transforms ---- */

static void assert_xform_consistent(const struct xform *t, double tol)
{
	mat4 id = mat_identity();
	mat4 a = mat_mul(&t->fwd, &t->inv), b = mat_mul(&t->inv, &t->fwd);
	assert_mat_near(&a, &id, tol);
	assert_mat_near(&b, &id, tol);
}

static void test_xform_identity(void **state)
{
	(void)state;
	struct xform t = xform_identity();
	assert_true(mat_is_identity(&t.fwd));
	assert_true(mat_is_identity(&t.inv));
	struct xform r = xform_rotate(v3(0, 0, 0));
	assert_true(mat_is_identity(&r.fwd));
	struct xform s = xform_scale(v3(1, 1, 1));
	assert_true(mat_is_identity(&s.fwd));
	assert_true(mat_is_identity(&s.inv));
	struct xform tr = xform_translate(v3(0, 0, 0));
	assert_true(mat_is_identity(&tr.fwd));
}

static void test_xform_translate(void **state)
{
	(void)state;
	struct xform t = xform_translate(v3(1, -2, 3.5));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 1, 1)), 2, -1, 4.5);
	assert_vec_exact(mat_point(&t.inv, v3(2, -1, 4.5)), 1, 1, 1);
	assert_vec_exact(mat_dir(&t.fwd, v3(1, 1, 1)), 1, 1, 1);
	assert_xform_consistent(&t, 0);
}

static void test_xform_scale(void **state)
{
	(void)state;
	struct xform s = xform_scale(v3(2, -3, 0.5));
	assert_vec_exact(mat_point(&s.fwd, v3(1, 1, 1)), 2, -3, 0.5);
	assert_vec_exact(mat_point(&s.inv, v3(2, -3, 0.5)), 1, 1, 1);
	assert_vec_exact(mat_dir(&s.fwd, v3(1, 2, 4)), 2, -6, 2);
	assert_xform_consistent(&s, 1e-16);
	/* A zero component: forward as given, inverse the identity. */
	struct xform z = xform_scale(v3(2, 0, 1));
	assert_vec_exact(mat_point(&z.fwd, v3(1, 1, 1)), 2, 0, 1);
	assert_true(mat_is_identity(&z.inv));
}

static void test_xform_rotate_quarter_turns_exact(void **state)
{
	(void)state;
	/* POV-Ray's left-handed frame: these hold bit for bit. */
	struct xform ry = xform_rotate(v3(0, 90, 0));
	assert_vec_exact(mat_point(&ry.fwd, v3(1, 0, 0)), 0, 0, -1);
	assert_vec_exact(mat_point(&ry.fwd, v3(0, 0, 1)), 1, 0, 0);
	assert_vec_exact(mat_point(&ry.fwd, v3(0, 1, 0)), 0, 1, 0);
	struct xform rx = xform_rotate(v3(90, 0, 0));
	assert_vec_exact(mat_point(&rx.fwd, v3(0, 1, 0)), 0, 0, 1);
	assert_vec_exact(mat_point(&rx.fwd, v3(0, 0, 1)), 0, -1, 0);
	assert_vec_exact(mat_point(&rx.fwd, v3(1, 0, 0)), 1, 0, 0);
	struct xform rz = xform_rotate(v3(0, 0, 90));
	assert_vec_exact(mat_point(&rz.fwd, v3(1, 0, 0)), 0, 1, 0);
	assert_vec_exact(mat_point(&rz.fwd, v3(0, 1, 0)), -1, 0, 0);
	assert_vec_exact(mat_point(&rz.fwd, v3(0, 0, 1)), 0, 0, 1);

	/* Other multiples of 90, including negative and past a full turn. */
	struct xform t;
	t = xform_rotate(v3(0, 180, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), -1, 0, 0);
	t = xform_rotate(v3(0, 270, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 0, 0, 1);
	t = xform_rotate(v3(0, -90, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 0, 0, 1);
	t = xform_rotate(v3(0, 360, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 1, 0, 0);
	t = xform_rotate(v3(0, 450, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 0, 0, -1);
	t = xform_rotate(v3(0, -270, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 0, 0, -1);
	t = xform_rotate(v3(-180, 0, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(0, 1, 0)), 0, -1, 0);
	t = xform_rotate(v3(0, 0, 720));
	assert_true(mat_is_identity(&t.fwd));
	/* The inverse undoes it exactly. */
	assert_vec_exact(mat_point(&ry.inv, v3(0, 0, -1)), 1, 0, 0);
	assert_vec_exact(mat_point(&rx.inv, v3(0, 0, 1)), 0, 1, 0);
	assert_vec_exact(mat_point(&rz.inv, v3(0, 1, 0)), 1, 0, 0);
}

static void test_xform_rotate_general_angle(void **state)
{
	(void)state;
	double a = 30 * M_PI / 180, c = cos(a), s = sin(a);
	struct xform t = xform_rotate(v3(0, 30, 0));
	assert_vec_near(mat_point(&t.fwd, v3(1, 0, 0)), c, 0, -s, 1e-15);
	assert_vec_near(mat_point(&t.fwd, v3(0, 0, 1)), s, 0, c, 1e-15);
	t = xform_rotate(v3(30, 0, 0));
	assert_vec_near(mat_point(&t.fwd, v3(0, 1, 0)), 0, c, s, 1e-15);
	t = xform_rotate(v3(0, 0, 30));
	assert_vec_near(mat_point(&t.fwd, v3(1, 0, 0)), c, s, 0, 1e-15);
	/* A non-integral multiple of 90 is not snapped. */
	t = xform_rotate(v3(0, 0, 90.5));
	double b = 90.5 * M_PI / 180;
	assert_vec_near(mat_point(&t.fwd, v3(1, 0, 0)), cos(b), sin(b), 0, 1e-15);
	assert_true(mat_point(&t.fwd, v3(1, 0, 0)).x < 0);
	/* Lengths are kept and the inverse is exact to rounding. */
	t = xform_rotate(v3(17, -33, 71.5));
	assert_near(v3_len(mat_point(&t.fwd, v3(1, 2, 3))), sqrt(14), 1e-14);
	assert_xform_consistent(&t, 1e-15);
}

static void test_xform_rotate_order(void **state)
{
	(void)state;
	/* rotate <90,90,0>: x first takes y to z, then y takes z to x. (Turning
	 * about y first would leave y alone and x would take it to z.) */
	struct xform t = xform_rotate(v3(90, 90, 0));
	assert_vec_exact(mat_point(&t.fwd, v3(0, 1, 0)), 1, 0, 0);
	/* rotate <90,0,90>: x takes y to z, which z leaves alone. */
	t = xform_rotate(v3(90, 0, 90));
	assert_vec_exact(mat_point(&t.fwd, v3(0, 1, 0)), 0, 0, 1);
	/* rotate <0,90,90>: y takes z to x, then z takes x to y. */
	t = xform_rotate(v3(0, 90, 90));
	assert_vec_exact(mat_point(&t.fwd, v3(0, 0, 1)), 0, 1, 0);
	/* In general it equals the three single rotations composed. */
	struct xform rx = xform_rotate(v3(20, 0, 0)), ry = xform_rotate(v3(0, -35, 0)),
		rz = xform_rotate(v3(0, 0, 50));
	struct xform yx = xform_compose(&ry, &rx), zyx = xform_compose(&rz, &yx);
	t = xform_rotate(v3(20, -35, 50));
	assert_mat_near(&t.fwd, &zyx.fwd, 1e-15);
	assert_mat_near(&t.inv, &zyx.inv, 1e-15);
}

static void test_xform_matrix(void **state)
{
	(void)state;
	/* matrix <1,0,0, 0,1,0, 0,0,1, 2,3,4> is translate <2,3,4>. */
	static const double tr[12] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 2, 3, 4};
	struct xform t = xform_matrix(tr);
	assert_vec_exact(mat_point(&t.fwd, v3(1, 1, 1)), 3, 4, 5);
	assert_vec_exact(mat_point(&t.inv, v3(3, 4, 5)), 1, 1, 1);
	/* Rows are the images of x, y and z: a shear taking y to <1,1,0>. */
	static const double sh[12] = {1, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0};
	t = xform_matrix(sh);
	assert_vec_exact(mat_point(&t.fwd, v3(0, 1, 0)), 1, 1, 0);
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 1, 0, 0);
	assert_vec_exact(mat_point(&t.fwd, v3(2, 3, 4)), 5, 3, 4);
	assert_vec_near(mat_point(&t.inv, v3(5, 3, 4)), 2, 3, 4, 1e-15);
	/* A general one: x -> <1,2,3>, y -> <4,5,6.5>, z -> <7,8,11>, + <1,1,1>. */
	static const double g[12] = {1, 2, 3, 4, 5, 6.5, 7, 8, 11, 1, 1, 1};
	t = xform_matrix(g);
	assert_vec_exact(mat_point(&t.fwd, v3(1, 0, 0)), 2, 3, 4);
	assert_vec_exact(mat_point(&t.fwd, v3(0, 1, 0)), 5, 6, 7.5);
	assert_vec_exact(mat_point(&t.fwd, v3(0, 0, 1)), 8, 9, 12);
	assert_xform_consistent(&t, 1e-13);
	/* Singular: forward as given, inverse the identity. */
	static const double s[12] = {1, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
	t = xform_matrix(s);
	assert_vec_exact(mat_point(&t.fwd, v3(1, 2, 3)), 1, 2, 0);
	assert_true(mat_is_identity(&t.inv));
}

static void test_xform_compose_invert(void **state)
{
	(void)state;
	/* scale 2 translate x: the scale applies first. */
	struct xform s = xform_scale(v3(2, 2, 2)), t = xform_translate(v3(1, 0, 0));
	struct xform c = xform_compose(&t, &s);
	assert_vec_exact(mat_point(&c.fwd, v3(1, 1, 1)), 3, 2, 2);
	assert_vec_exact(mat_point(&c.inv, v3(3, 2, 2)), 1, 1, 1);
	assert_xform_consistent(&c, 0);
	/* The other order differs. */
	struct xform d = xform_compose(&s, &t);
	assert_vec_exact(mat_point(&d.fwd, v3(1, 1, 1)), 4, 2, 2);
	/* Translate, rotate, scale non-uniformly, in that order. */
	struct xform r = xform_rotate(v3(0, 0, 90)), ns = xform_scale(v3(1, 3, 1));
	struct xform tr = xform_compose(&r, &t), all = xform_compose(&ns, &tr);
	/* <0,0,0> -> <1,0,0> -> <0,1,0> -> <0,3,0>. */
	assert_vec_exact(mat_point(&all.fwd, v3(0, 0, 0)), 0, 3, 0);
	assert_xform_consistent(&all, 1e-15);
	/* Invert swaps the two matrices. */
	struct xform i = xform_invert(&all);
	assert_mat_near(&i.fwd, &all.inv, 0);
	assert_mat_near(&i.inv, &all.fwd, 0);
	assert_vec_exact(mat_point(&i.fwd, v3(0, 3, 0)), 0, 0, 0);
	/* Composing with the inverse gives the identity. */
	struct xform e = xform_compose(&i, &all);
	mat4 id = mat_identity();
	assert_mat_near(&e.fwd, &id, 1e-15);
	assert_mat_near(&e.inv, &id, 1e-15);
}

static void test_mat_bounds(void **state)
{
	(void)state;
	struct aabb cube = {v3(-1, -1, -1), v3(1, 1, 1)};
	struct xform t = xform_translate(v3(10, 0, -5));
	struct aabb b = mat_bounds(&t.fwd, cube);
	assert_vec_exact(b.lo, 9, -1, -6);
	assert_vec_exact(b.hi, 11, 1, -4);
	/* A 45 degree turn about z widens x and y to sqrt(2). */
	struct xform r = xform_rotate(v3(0, 0, 45));
	b = mat_bounds(&r.fwd, cube);
	assert_vec_near(b.lo, -sqrt(2), -sqrt(2), -1, 1e-15);
	assert_vec_near(b.hi, sqrt(2), sqrt(2), 1, 1e-15);
	/* Rotating an off-centre box by 90 about y: x in [2,4] goes to z in [-4,-2]. */
	struct aabb off = {v3(2, 0, 0), v3(4, 1, 1)};
	struct xform ry = xform_rotate(v3(0, 90, 0));
	b = mat_bounds(&ry.fwd, off);
	assert_vec_exact(b.lo, 0, 0, -4);
	assert_vec_exact(b.hi, 1, 1, -2);
	/* Negative scale swaps the ends. */
	struct xform s = xform_scale(v3(-2, 1, 3));
	b = mat_bounds(&s.fwd, off);
	assert_vec_exact(b.lo, -8, 0, 0);
	assert_vec_exact(b.hi, -4, 1, 3);
	/* Infinite (or empty) boxes pass through unchanged. */
	struct aabb inf = {v3(-INFINITY, -INFINITY, -INFINITY), v3(INFINITY, INFINITY, INFINITY)};
	b = mat_bounds(&r.fwd, inf);
	assert_true(isinf(b.lo.x) && b.lo.x < 0 && isinf(b.hi.z) && b.hi.z > 0);
	b = mat_bounds(&r.fwd, aabb_empty());
	assert_false(aabb_is_finite(b));
	assert_true(b.lo.x > b.hi.x);
}

/* ---- hash.h ---- */

static void test_hash_uniform(void **state)
{
	(void)state;
	double sum = 0, lo = 1, hi = 0;
	int n = 0, buckets[10] = {0};
	for (uint32_t x = 0; x < 64; x++)
		for (uint32_t y = 0; y < 64; y++)
			for (uint32_t s = 0; s < 8; s++) {
				double u = hash_uniform(x, y, s, 3);
				if (!(u >= 0 && u < 1))
					fail_msg("hash_uniform(%u,%u,%u,3) = %.17g outside [0,1)", x, y, s, u);
				/* Deterministic: the same arguments give the same bits. */
				assert_true(u == hash_uniform(x, y, s, 3));
				sum += u;
				lo = fmin(lo, u);
				hi = fmax(hi, u);
				buckets[(int)(u * 10)]++;
				n++;
			}
	/* 32768 samples: mean within ~6 standard deviations of 1/2, every
	 * tenth of the range about equally full. */
	assert_near(sum / n, 0.5, 0.01);
	assert_true(lo < 0.001 && hi > 0.999);
	for (int k = 0; k < 10; k++)
		assert_in_range(buckets[k], n / 10 - 400, n / 10 + 400);
	/* Extreme arguments stay in range. */
	double u = hash_uniform(UINT32_MAX, UINT32_MAX, UINT32_MAX, UINT32_MAX);
	assert_true(u >= 0 && u < 1);
}

static void test_hash_arguments_matter(void **state)
{
	(void)state;
	double base = hash_uniform(10, 20, 30, 40);
	assert_true(base != hash_uniform(11, 20, 30, 40));
	assert_true(base != hash_uniform(10, 21, 30, 40));
	assert_true(base != hash_uniform(10, 20, 31, 40));
	assert_true(base != hash_uniform(10, 20, 30, 41));
	/* Swapping x and y, or sample and purpose, gives a different value. */
	assert_true(hash_uniform(1, 2, 0, 0) != hash_uniform(2, 1, 0, 0));
	assert_true(hash_uniform(0, 0, 1, 2) != hash_uniform(0, 0, 2, 1));
	/* hash_mix is a bijection's worth of scrambling: neighbours differ a lot. */
	uint64_t a = hash_mix(1), b = hash_mix(2);
	int bits = __builtin_popcountll(a ^ b);
	assert_in_range(bits, 16, 48);
	assert_true(hash_mix(12345) == hash_mix(12345));
}

/* ---- solve.h ---- */

static void test_solve_quadratic_basic(void **state)
{
	(void)state;
	double r[2];
	/* (t - 1)(t - 3) */
	assert_int_equal(solve_quadratic(1, -4, 3, r), 2);
	assert_near(r[0], 1, 0);
	assert_near(r[1], 3, 0);
	/* The same with a < 0: still ascending. */
	assert_int_equal(solve_quadratic(-1, 4, -3, r), 2);
	assert_near(r[0], 1, 0);
	assert_near(r[1], 3, 0);
	/* 2(t + 2)(t - 0.5) */
	assert_int_equal(solve_quadratic(2, 3, -2, r), 2);
	assert_near(r[0], -2, 0);
	assert_near(r[1], 0.5, 0);
	/* b = 0: t^2 - 4 */
	assert_int_equal(solve_quadratic(1, 0, -4, r), 2);
	assert_near(r[0], -2, 0);
	assert_near(r[1], 2, 0);
	/* c = 0: a root at exactly zero. */
	assert_int_equal(solve_quadratic(1, -5, 0, r), 2);
	assert_near(r[0], 0, 0);
	assert_near(r[1], 5, 0);
	assert_int_equal(solve_quadratic(1, 5, 0, r), 2);
	assert_near(r[0], -5, 0);
	assert_near(r[1], 0, 0);
}

static void test_solve_quadratic_degenerate(void **state)
{
	(void)state;
	double r[2] = {42, 42};
	/* No real roots. */
	assert_int_equal(solve_quadratic(1, 0, 1, r), 0);
	assert_int_equal(solve_quadratic(1, 1, 1, r), 0);
	/* A double root. */
	assert_int_equal(solve_quadratic(1, -2, 1, r), 1);
	assert_near(r[0], 1, 0);
	assert_int_equal(solve_quadratic(4, 4, 1, r), 1);
	assert_near(r[0], -0.5, 0);
	assert_int_equal(solve_quadratic(1, 0, 0, r), 1);
	assert_near(r[0], 0, 0);
	/* Linear. */
	assert_int_equal(solve_quadratic(0, 2, -4, r), 1);
	assert_near(r[0], 2, 0);
	/* Nothing at all. */
	assert_int_equal(solve_quadratic(0, 0, 1, r), 0);
	assert_int_equal(solve_quadratic(0, 0, 0, r), 0);
}

static void test_solve_quadratic_cancellation(void **state)
{
	(void)state;
	double r[2];
	/* t^2 - 1e8 t + 1: the roots are 1e8 and 1e-8 (to 1e-16 relative);
	 * the textbook formula loses every digit of the small one. */
	assert_int_equal(solve_quadratic(1, -1e8, 1, r), 2);
	assert_near(r[0] / 1e-8, 1, 4e-16);
	assert_near(r[1] / 1e8, 1, 4e-16);
	/* Mirrored. */
	assert_int_equal(solve_quadratic(1, 1e8, 1, r), 2);
	assert_near(r[0] / -1e8, 1, 4e-16);
	assert_near(r[1] / -1e-8, 1, 4e-16);
	/* Scaled coefficients give the same roots. */
	assert_int_equal(solve_quadratic(1e-3, -1e5, 1e-3, r), 2);
	assert_near(r[0] / 1e-8, 1, 1e-15);
	assert_near(r[1] / 1e8, 1, 1e-15);
	/* Roots 1e-12 and 3: (t - 1e-12)(t - 3) = t^2 - (3 + 1e-12) t + 3e-12. */
	assert_int_equal(solve_quadratic(1, -(3 + 1e-12), 3e-12, r), 2);
	assert_near(r[0] / 1e-12, 1, 1e-15);
	assert_near(r[1], 3, 1e-15);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_vec_arith),
		cmocka_unit_test(test_vec_cross_len_norm),
		cmocka_unit_test(test_vec_reflect),
		cmocka_unit_test(test_aabb),
		cmocka_unit_test(test_mat_identity),
		cmocka_unit_test(test_mat_mul),
		cmocka_unit_test(test_mat_transpose),
		cmocka_unit_test(test_mat_inverse),
		cmocka_unit_test(test_mat_inverse_singular),
		cmocka_unit_test(test_mat_point_dir),
		cmocka_unit_test(test_mat_normal),
		cmocka_unit_test(test_xform_identity),
		cmocka_unit_test(test_xform_translate),
		cmocka_unit_test(test_xform_scale),
		cmocka_unit_test(test_xform_rotate_quarter_turns_exact),
		cmocka_unit_test(test_xform_rotate_general_angle),
		cmocka_unit_test(test_xform_rotate_order),
		cmocka_unit_test(test_xform_matrix),
		cmocka_unit_test(test_xform_compose_invert),
		cmocka_unit_test(test_mat_bounds),
		cmocka_unit_test(test_hash_uniform),
		cmocka_unit_test(test_hash_arguments_matter),
		cmocka_unit_test(test_solve_quadratic_basic),
		cmocka_unit_test(test_solve_quadratic_degenerate),
		cmocka_unit_test(test_solve_quadratic_cancellation),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* mat.c: 4x4 affine transforms (see mat.h for the conventions). */
#include "math/mat.h"

#include <string.h>

mat4 mat_identity(void)
{
	mat4 r;
	memset(&r, 0, sizeof r);
	r.m[0][0] = r.m[1][1] = r.m[2][2] = r.m[3][3] = 1.0;
	return r;
}

mat4 mat_mul(const mat4 *a, const mat4 *b)
{
	mat4 r;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			double s = 0;
			for (int k = 0; k < 4; k++)
				s += a->m[i][k] * b->m[k][j];
			r.m[i][j] = s;
		}
	return r;
}

mat4 mat_transpose(const mat4 *a)
{
	mat4 r;
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			r.m[i][j] = a->m[j][i];
	return r;
}

bool mat_is_identity(const mat4 *a)
{
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++)
			if (a->m[i][j] != (i == j ? 1.0 : 0.0))
				return false;
	return true;
}

/* Affine inverse: invert the 3x3 part by cofactors (in double precision this
 * is exact enough for any scale a scene uses), then the translation. */
bool mat_inverse(const mat4 *a, mat4 *out)
{
	const double (*m)[4] = a->m;
	double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
	double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
	double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
	double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
	*out = mat_identity();
	if (det == 0 || !isfinite(det))
		return false;
	double id = 1.0 / det;
	mat4 r = mat_identity();
	r.m[0][0] = c00 * id;
	r.m[1][0] = c01 * id;
	r.m[2][0] = c02 * id;
	r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
	r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
	r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
	r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
	r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
	r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
	for (int i = 0; i < 3; i++)
		r.m[i][3] = -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
	*out = r;
	return true;
}

vec3 mat_point(const mat4 *m, vec3 p)
{
	return v3(m->m[0][0] * p.x + m->m[0][1] * p.y + m->m[0][2] * p.z + m->m[0][3],
	          m->m[1][0] * p.x + m->m[1][1] * p.y + m->m[1][2] * p.z + m->m[1][3],
	          m->m[2][0] * p.x + m->m[2][1] * p.y + m->m[2][2] * p.z + m->m[2][3]);
}

vec3 mat_dir(const mat4 *m, vec3 d)
{
	return v3(m->m[0][0] * d.x + m->m[0][1] * d.y + m->m[0][2] * d.z,
	          m->m[1][0] * d.x + m->m[1][1] * d.y + m->m[1][2] * d.z,
	          m->m[2][0] * d.x + m->m[2][1] * d.y + m->m[2][2] * d.z);
}

vec3 mat_normal(const mat4 *inv, vec3 n)
{
	return v3(inv->m[0][0] * n.x + inv->m[1][0] * n.y + inv->m[2][0] * n.z,
	          inv->m[0][1] * n.x + inv->m[1][1] * n.y + inv->m[2][1] * n.z,
	          inv->m[0][2] * n.x + inv->m[1][2] * n.y + inv->m[2][2] * n.z);
}

struct xform xform_identity(void)
{
	struct xform t = {mat_identity(), mat_identity(), true};
	return t;
}

struct xform xform_translate(vec3 v)
{
	struct xform t = xform_identity();
	t.fwd.m[0][3] = v.x;
	t.fwd.m[1][3] = v.y;
	t.fwd.m[2][3] = v.z;
	t.inv.m[0][3] = -v.x;
	t.inv.m[1][3] = -v.y;
	t.inv.m[2][3] = -v.z;
	return t;
}

struct xform xform_scale(vec3 s)
{
	struct xform t = xform_identity();
	t.fwd.m[0][0] = s.x;
	t.fwd.m[1][1] = s.y;
	t.fwd.m[2][2] = s.z;
	t.simple = s.x == s.y && s.y == s.z;
	if (s.x != 0 && s.y != 0 && s.z != 0) {
		t.inv.m[0][0] = 1.0 / s.x;
		t.inv.m[1][1] = 1.0 / s.y;
		t.inv.m[2][2] = 1.0 / s.z;
	}
	return t;
}

/* One rotation about a principal axis, with sines of exact multiples of
 * 90 degrees snapped to exact values so that rotate y*90 maps x to -z
 * exactly. */
static mat4 axis_rotation(int axis, double degrees, int snap)
{
	mat4 r = mat_identity();
	double a = degrees * (M_PI / 180.0);
	double s = sin(a), c = cos(a);
	double q = degrees / 90.0;
	if (snap && q == floor(q)) {
		long k = ((long)fmod(q, 4.0) + 4) % 4;
		static const double sn[4] = {0, 1, 0, -1}, cs[4] = {1, 0, -1, 0};
		s = sn[k];
		c = cs[k];
	}
	int i = (axis + 1) % 3, j = (axis + 2) % 3;
	r.m[i][i] = c;
	r.m[i][j] = -s;
	r.m[j][i] = s;
	r.m[j][j] = c;
	return r;
}

static struct xform rotation(vec3 deg, int snap)
{
	mat4 rx = axis_rotation(0, deg.x, snap), ry = axis_rotation(1, deg.y, snap),
	     rz = axis_rotation(2, deg.z, snap);
	mat4 yx = mat_mul(&ry, &rx);
	struct xform t;
	t.fwd = mat_mul(&rz, &yx);
	/* A rotation's inverse is its transpose. */
	t.inv = mat_transpose(&t.fwd);
	t.simple = true;
	return t;
}

struct xform xform_rotate(vec3 deg)
{
	return rotation(deg, 1);
}

struct xform xform_rotate_plain(vec3 deg)
{
	return rotation(deg, 0);
}

mat4 mat_axis_rotation(vec3 axis, double degrees)
{
	double a = degrees * (M_PI / 180.0);
	double c = cos(a), s = sin(a), t = 1.0 - c;
	mat4 r = mat_identity();
	r.m[0][0] = t * (axis.x * axis.x) + c;
	r.m[0][1] = t * (axis.x * axis.y) - s * axis.z;
	r.m[0][2] = t * (axis.x * axis.z) + s * axis.y;
	r.m[1][0] = t * (axis.x * axis.y) + s * axis.z;
	r.m[1][1] = t * (axis.y * axis.y) + c;
	r.m[1][2] = t * (axis.y * axis.z) - s * axis.x;
	r.m[2][0] = t * (axis.x * axis.z) - s * axis.y;
	r.m[2][1] = t * (axis.y * axis.z) + s * axis.x;
	r.m[2][2] = t * (axis.z * axis.z) + c;
	return r;
}

struct xform xform_matrix(const double v[12])
{
	struct xform t = xform_identity();
	/* POV-Ray's matrix rows are the images of x, y, z and the translation,
	 * for row vectors; ours act on columns, so they become our columns. */
	for (int r = 0; r < 4; r++)
		for (int c = 0; c < 3; c++)
			t.fwd.m[c][r] = v[r * 3 + c];
	t.simple = false;
	mat_inverse(&t.fwd, &t.inv);
	return t;
}

struct xform xform_compose(const struct xform *outer, const struct xform *inner)
{
	struct xform t;
	t.fwd = mat_mul(&outer->fwd, &inner->fwd);
	t.inv = mat_mul(&inner->inv, &outer->inv);
	t.simple = false;
	return t;
}

struct xform xform_invert(const struct xform *a)
{
	struct xform t = {a->inv, a->fwd, false};
	return t;
}

struct aabb mat_bounds(const mat4 *m, struct aabb b)
{
	if (!aabb_is_finite(b))
		return b;
	struct aabb r = aabb_empty();
	for (int i = 0; i < 8; i++) {
		vec3 p = v3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
		r = aabb_add_point(r, mat_point(m, p));
	}
	return r;
}

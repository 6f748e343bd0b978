/* tri.c: the watertight ray/triangle test (see tri.h). */
#include "geom/tri.h"

/* The edge functions need every product rounded on its own: a fused
 * multiply-add can give a difference of products the wrong sign, and then
 * rays slip between triangles. ISO C modes do not contract by default, GNU
 * modes and clang may; these switch it off for this file whatever the
 * flags. */
#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

static inline double comp(vec3 v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

bool tri_ray_init(struct tri_ray *tr, const struct ray *r)
{
	vec3 d = r->dir;
	if (!(isfinite(d.x) && isfinite(d.y) && isfinite(d.z)))
		return false;
	int kz = 0;
	if (fabs(d.y) > fabs(d.x)) kz = 1;
	if (fabs(d.z) > fabs(comp(d, kz))) kz = 2;
	double dz = comp(d, kz);
	if (dz == 0)
		return false; /* the dominant component is zero: a zero direction */
	int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
	if (dz < 0) { /* keep the winding: swap the other two axes */
		int k = kx; kx = ky; ky = k;
	}
	tr->org = r->org;
	tr->kx = kx;
	tr->ky = ky;
	tr->kz = kz;
	tr->sx = comp(d, kx) / dz;
	tr->sy = comp(d, ky) / dz;
	tr->sz = 1.0 / dz;
	return true;
}

/* The 2D edge function px*qy - py*qx of two sheared vertices, with an exact
 * sign. When the rounded products are equal the double difference is 0 and
 * the true value is the difference of their rounding errors, which fma
 * gives exactly (barring underflow). A shared edge evaluated from the other
 * triangle (p and q swapped) gives exactly the negated value. */
static inline double edge(double px, double py, double qx, double qy)
{
	double a = px * qy, b = py * qx;
	double e = a - b;
	if (e != 0)
		return e;
	return fma(px, qy, -a) - fma(py, qx, -b);
}

/* The sign of an edge function that is exactly zero: the ray's 2D position
 * is perturbed by (eps^2, eps), which moves the value by dx*eps - dy*eps^2
 * with d = q - p. Zero only for an edge of zero projected length. The two
 * triangles on a shared edge see d negated, so exactly one of them takes
 * the point. */
static inline double tiebreak(double px, double py, double qx, double qy)
{
	double dx = qx - px, dy = qy - py;
	return dx != 0 ? dx : -dy;
}

bool tri_intersect(const struct tri_ray *tr, vec3 a, vec3 b, vec3 c, double tmin, double tmax, struct tri_hit *out)
{
	vec3 A = v3_sub(a, tr->org), B = v3_sub(b, tr->org), C = v3_sub(c, tr->org);
	int kx = tr->kx, ky = tr->ky, kz = tr->kz;
	double az = comp(A, kz), bz = comp(B, kz), cz = comp(C, kz);
	double ax = comp(A, kx) - tr->sx * az, ay = comp(A, ky) - tr->sy * az;
	double bx = comp(B, kx) - tr->sx * bz, by = comp(B, ky) - tr->sy * bz;
	double cx = comp(C, kx) - tr->sx * cz, cy = comp(C, ky) - tr->sy * cz;

	double u = edge(cx, cy, bx, by); /* edge c->b, opposite a */
	double v = edge(ax, ay, cx, cy); /* edge a->c, opposite b */
	double w = edge(bx, by, ax, ay); /* edge b->a, opposite c */
	double su = u != 0 ? u : tiebreak(cx, cy, bx, by);
	double sv = v != 0 ? v : tiebreak(ax, ay, cx, cy);
	double sw = w != 0 ? w : tiebreak(bx, by, ax, ay);
	if (!((su > 0 && sv > 0 && sw > 0) || (su < 0 && sv < 0 && sw < 0)))
		return false; /* outside, or on an edge of zero projected length */

	/* u, v, w share a sign and are not all zero (their exact sum is twice
	 * the projected area), so det is zero only on underflow. */
	double det = u + v + w;
	if (det == 0)
		return false;
	double T = u * (tr->sz * az) + v * (tr->sz * bz) + w * (tr->sz * cz);
	double t = T / det;
	if (!(t > tmin && t < tmax)) /* also rejects NaN */
		return false;
	out->t = t;
	out->u = v / det;
	out->v = w / det;
	return true;
}

bool tri_degenerate(vec3 a, vec3 b, vec3 c)
{
	vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
	if (!(isfinite(n.x) && isfinite(n.y) && isfinite(n.z)))
		return true; /* a non-finite corner, or an overflowing area */
	return n.x == 0 && n.y == 0 && n.z == 0;
}

bool tri_smooth_degenerate(vec3 a, vec3 na, vec3 b, vec3 nb, vec3 c, vec3 nc)
{
	if (tri_degenerate(a, b, c))
		return true;
	vec3 n = v3_cross(v3_sub(b, a), v3_sub(c, a));
	double d0 = v3_dot(n, na), d1 = v3_dot(n, nb), d2 = v3_dot(n, nc);
	return !((d0 > 0 && d1 > 0 && d2 > 0) || (d0 < 0 && d1 < 0 && d2 < 0));
}

void tri_barycentric(vec3 a, vec3 b, vec3 c, vec3 p, double *u, double *v)
{
	vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a), ap = v3_sub(p, a);
	vec3 n = v3_cross(e1, e2);
	double nn = v3_dot(n, n);
	if (!(nn > 0) || !isfinite(nn)) {
		*u = *v = 0;
		return;
	}
	*u = v3_dot(v3_cross(ap, e2), n) / nn;
	*v = v3_dot(v3_cross(e1, ap), n) / nn;
}

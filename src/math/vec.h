/* vec.h: three-component double-precision vectors, the currency of all
 * geometry and ray math in lucent. Everything is inline; vec3 is a small
 * value type passed and returned by value. */
#ifndef LUCENT_VEC_H
#define LUCENT_VEC_H

#include <math.h>

typedef struct vec3 {
	double x, y, z;
} vec3;

static inline vec3 v3(double x, double y, double z) { vec3 r = {x, y, z}; return r; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
	return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_len(vec3 a) { return sqrt(v3_dot(a, a)); }
/* a + b*s, the point at parameter s along a ray. */
static inline vec3 v3_madd(vec3 a, vec3 b, double s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }

/* Unit vector along a; a zero vector stays zero (never NaN). */
static inline vec3 v3_norm(vec3 a)
{
	double l = v3_len(a);
	return l > 0 ? v3_scale(a, 1.0 / l) : a;
}

static inline double v3_maxabs(vec3 a)
{
	double m = fabs(a.x);
	if (fabs(a.y) > m) m = fabs(a.y);
	if (fabs(a.z) > m) m = fabs(a.z);
	return m;
}

static inline vec3 v3_min(vec3 a, vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
static inline double v3_get(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

/* Mirror direction d about unit normal n. */
static inline vec3 v3_reflect(vec3 d, vec3 n) { return v3_madd(d, n, -2.0 * v3_dot(d, n)); }

/* A ray: origin and direction. The direction need not be unit length; in
 * object space it is the world direction carried through the inverse
 * transform, so that parameters t agree between the two spaces. */
struct ray {
	vec3 org;
	vec3 dir;
};

/* An axis-aligned bounding box. An empty box has lo > hi. */
struct aabb {
	vec3 lo, hi;
};

static inline struct aabb aabb_empty(void)
{
	struct aabb b = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
	return b;
}
static inline struct aabb aabb_union(struct aabb a, struct aabb b)
{
	struct aabb r = {v3_min(a.lo, b.lo), v3_max(a.hi, b.hi)};
	return r;
}
static inline struct aabb aabb_add_point(struct aabb a, vec3 p)
{
	struct aabb r = {v3_min(a.lo, p), v3_max(a.hi, p)};
	return r;
}
static inline int aabb_is_finite(struct aabb a)
{
	return isfinite(a.lo.x) && isfinite(a.lo.y) && isfinite(a.lo.z) &&
	       isfinite(a.hi.x) && isfinite(a.hi.y) && isfinite(a.hi.z);
}
static inline vec3 aabb_center(struct aabb a) { return v3_scale(v3_add(a.lo, a.hi), 0.5); }
static inline double aabb_area(struct aabb a)
{
	vec3 d = v3_sub(a.hi, a.lo);
	if (d.x < 0 || d.y < 0 || d.z < 0) return 0;
	return 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

#endif

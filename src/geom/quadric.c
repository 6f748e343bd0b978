/* quadric.c: quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }, the surface
 * f(p) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0
 * with the inside where f <= 0 (POV-Ray counts points on the surface as
 * inside). Unbounded in general; when the solid is an ellipsoid its box is
 * computed exactly. */
#include "geom/shapes.h"

#include <float.h>
#include <stdlib.h>

struct quadric {
	struct object base;
	double a, b, c, d, e, f, g, h, i, j; /* the coefficients A..J */
	struct aabb box;                     /* object-space bounds, decided once */
};

static double eval(const struct quadric *q, vec3 p)
{
	return p.x * (q->a * p.x + q->d * p.y + q->e * p.z + q->g) + p.y * (q->b * p.y + q->f * p.z + q->h) +
	       p.z * (q->c * p.z + q->i) + q->j;
}

/* hb^2 - a c for f(t) = a t^2 + 2 hb t + c along the ray. When the two
 * products nearly cancel (the roots are close: a nearly tangent ray), c's
 * own rounding, which grows with the origin's distance, would swamp the
 * result; then the discriminant is taken as -a f(t_v) at the vertex
 * t_v = -hb/a, evaluated at a point near the surface, as the sphere forms
 * it from the ray's closest approach. */
static double discriminant(const struct quadric *q, const struct ray *r, double a, double hb, double c)
{
	double p = hb * hb, ac = a * c, d = p - ac;
	if (fabs(d) * 4 >= p + fabs(ac))
		return d;
	double tv = -hb / a;
	double dv = -a * eval(q, v3_madd(r->org, r->dir, tv));
	return isfinite(dv) ? dv : d;
}

/* The crossings of the ray with the surface, ascending: f along the ray is
 * a t^2 + 2 hb t + c. Returns 0, 1 (a = 0: one root, or a tangent touch
 * counted once by the linear case) or 2 (a double root twice, like the
 * sphere's tangent rays). A ray on which f is constant crosses nothing. */
static int roots(const struct quadric *q, const struct ray *r, double t[2])
{
	vec3 o = r->org, d = r->dir;
	double a = d.x * (q->a * d.x + q->d * d.y + q->e * d.z) + d.y * (q->b * d.y + q->f * d.z) + q->c * d.z * d.z;
	double hb = q->a * o.x * d.x + q->b * o.y * d.y + q->c * o.z * d.z +
	            0.5 * (q->d * (o.x * d.y + o.y * d.x) + q->e * (o.x * d.z + o.z * d.x) +
	                   q->f * (o.y * d.z + o.z * d.y) + q->g * d.x + q->h * d.y + q->i * d.z);
	double c = eval(q, o);
	if (a == 0) {
		if (hb == 0)
			return 0;
		t[0] = -c / (2 * hb);
		return isfinite(t[0]);
	}
	double disc = discriminant(q, r, a, hb, c);
	if (disc < 0)
		return 0;
	double qq = -(hb + copysign(sqrt(disc), hb));
	if (qq == 0) {
		t[0] = t[1] = 0; /* hb = disc = 0 makes c = 0 */
		return 2;
	}
	double t0 = qq / a, t1 = c / qq;
	int n = 0;
	if (isfinite(t0))
		t[n++] = t0;
	if (isfinite(t1))
		t[n++] = t1;
	if (n == 2 && t[0] > t[1]) {
		double tmp = t[0];
		t[0] = t[1];
		t[1] = tmp;
	}
	return n;
}

static bool quadric_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t[2];
	int n = roots((const struct quadric *)o, r, t);
	for (int i = 0; i < n; i++)
		if (t[i] > tmin && t[i] < tmax) {
			h->t = t[i];
			h->part = 0;
			return true;
		}
	return false;
}

static int quadric_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[2];
	int n = roots((const struct quadric *)o, r, t), k = 0;
	for (int i = 0; i < n && k < max; i++)
		if (t[i] > tmin && t[i] < tmax) {
			out[k].t = t[i];
			out[k].part = 0;
			out[k].obj = o;
			k++;
		}
	return k;
}

static bool quadric_inside(const struct object *o, vec3 p)
{
	return eval((const struct quadric *)o, p) <= 0;
}

/* The gradient of f. Where it vanishes (a cone's apex) any direction is as
 * good as another; +y keeps the result finite and non-zero. */
static vec3 quadric_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct quadric *q = (const struct quadric *)o;
	vec3 n = v3(2 * q->a * p.x + q->d * p.y + q->e * p.z + q->g, 2 * q->b * p.y + q->d * p.x + q->f * p.z + q->h,
	            2 * q->c * p.z + q->e * p.x + q->f * p.y + q->i);
	if (!(v3_dot(n, n) > 0) || !isfinite(v3_dot(n, n)))
		return v3(0, 1, 0);
	return n;
}

static struct aabb quadric_bounds(const struct object *o)
{
	return ((const struct quadric *)o)->box;
}

/* The solid f <= 0 is finite exactly when the quadratic part M (A, B, C on
 * the diagonal, D/2, E/2, F/2 off it) is positive definite. Then
 * f(p) = (p - m)' M (p - m) + f(m) with the centre m = -M^-1 (G,H,I)/2, the
 * solid is the ellipsoid (p - m)' M (p - m) <= -f(m), and its half-extent
 * along axis i is sqrt(-f(m) (M^-1)_ii). Nearly singular M (a cylinder or
 * paraboloid with rounded coefficients) is treated as unbounded, which is
 * always safe. */
static struct aabb ellipsoid_box(const struct quadric *q)
{
	const struct aabb inf = {{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
	double m00 = q->a, m11 = q->b, m22 = q->c, m01 = q->d / 2, m02 = q->e / 2, m12 = q->f / 2;
	double s = fmax(fmax(fabs(m00), fabs(m11)), fmax(fabs(m22), fmax(fabs(m01), fmax(fabs(m02), fabs(m12)))));
	if (!(s > 0) || !isfinite(s))
		return inf;
	/* Sylvester's criterion, with a margin against rounding. */
	double c00 = m11 * m22 - m12 * m12, c01 = m02 * m12 - m01 * m22, c02 = m01 * m12 - m02 * m11;
	double minor2 = m00 * m11 - m01 * m01;
	double det = m00 * c00 + m01 * c01 + m02 * c02;
	const double tol = 1e-12;
	if (!(m00 > tol * s && minor2 > tol * s * s && det > tol * s * s * s))
		return inf;
	double c11 = m00 * m22 - m02 * m02, c12 = m01 * m02 - m00 * m12, c22 = minor2;
	/* M^-1 = cofactors / det (M is symmetric). */
	double i00 = c00 / det, i01 = c01 / det, i02 = c02 / det, i11 = c11 / det, i12 = c12 / det,
	       i22 = c22 / det;
	vec3 m = v3(-0.5 * (i00 * q->g + i01 * q->h + i02 * q->i), -0.5 * (i01 * q->g + i11 * q->h + i12 * q->i),
	            -0.5 * (i02 * q->g + i12 * q->h + i22 * q->i));
	double fm = q->j + 0.5 * (q->g * m.x + q->h * m.y + q->i * m.z);
	if (!isfinite(fm) || !isfinite(v3_dot(m, m)))
		return inf;
	if (fm >= 0)
		return (struct aabb){m, m}; /* empty, or the single point m */
	/* The margin covers the rounding of the above: f(m) is a difference
	 * of terms as large as |J| + |(G,H,I).m|/2, and the extents go as its
	 * square root. */
	double big = fabs(q->j) + 0.5 * (fabs(q->g * m.x) + fabs(q->h * m.y) + fabs(q->i * m.z));
	double rel = 1e-9 + 8 * DBL_EPSILON * big / -fm;
	vec3 e = v3_scale(v3(sqrt(-fm * i00), sqrt(-fm * i11), sqrt(-fm * i22)), 1 + rel);
	return (struct aabb){v3_sub(m, e), v3_add(m, e)};
}

static struct object *quadric_copy(const struct object *o)
{
	struct quadric *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct quadric *)o;
	return &c->base;
}

static const struct object_ops quadric_ops = {
	.name = "quadric",
	.intersect = quadric_intersect,
	.all_hits = quadric_all_hits,
	.inside = quadric_inside,
	.normal = quadric_normal,
	.bounds = quadric_bounds,
	.copy = quadric_copy,
};

struct object *quadric_new(vec3 abc, vec3 def, vec3 ghi, double j, struct srcpos pos)
{
	struct quadric *q = calloc(1, sizeof *q);
	if (!q) abort();
	object_init(&q->base, &quadric_ops, pos);
	q->a = abc.x, q->b = abc.y, q->c = abc.z;
	q->d = def.x, q->e = def.y, q->f = def.z;
	q->g = ghi.x, q->h = ghi.y, q->i = ghi.z;
	q->j = j;
	q->box = ellipsoid_box(q);
	return &q->base;
}

/* lathe.c: lathe { spline n, points }: a curve in the (r, y) plane turned
 * about the y axis. The curve is kept as pieces, each a polynomial in u on
 * [0, 1] of degree 1 to 3 (r(u), y(u)); the curves are POV-Ray's, measured
 * with trace() to eight digits:
 * - linear_spline: the straight line from P[i] to P[i+1];
 * - quadratic_spline: the parabola through P[i-1], P[i], P[i+1] at
 *   u = -1, 0, 1, drawn from P[i] to P[i+1] (P[0] is only a control point);
 * - cubic_spline: Catmull-Rom, the Hermite cubic from P[i] to P[i+1] with
 *   tangents (P[i+1] - P[i-1]) / 2 and (P[i+2] - P[i]) / 2;
 * - bezier_spline: the cubic Bezier curve of each four points.
 *
 * A ray o + t d meets the surface where x^2 + z^2 = r(u)^2 and y = y(u).
 * With d.y != 0, t = (y(u) - o.y) / d.y, and x^2 + z^2 is a quadratic in t,
 * so the hits are the roots in [0, 1] of a polynomial in u of twice the
 * piece's degree (up to 6). With d.y = 0 the pieces' u come from
 * y(u) = o.y and t from the quadratic.
 *
 * The normal is POV-Ray's raw one: in the (r, y) plane it points to the
 * right of the curve's direction of travel, (y'(u), -r'(u)) (outward for a
 * curve drawn counter-clockwise with r to the right, inward otherwise); the
 * renderer turns it to face the ray. The bounds are the curve's extent, but
 * for bezier_spline the control points' (as POV-Ray's). The inside is where
 * a half-line from (r, y) towards +r crosses the curve an odd number of
 * times. */
#include "geom/shapes2.h"
#include "geom/solve.h"
#include "geom/spline2.h"
#include "geom/collect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One piece: r(u) = r[0] + r[1] u + r[2] u^2 + r[3] u^3, the same for y. */
struct lseg {
	double r[4], y[4];
	int deg;
	double rlo, rhi, ylo, yhi; /* the piece's extent */
};

struct lathe {
	struct object base;
	struct lseg *seg;
	int nseg;
	bool sturm;
	double rmax, ylo, yhi; /* bounds */
};

_Static_assert((int)LATHE_BEZIER_SPLINE == (int)SPLINE2_BEZIER && (int)LATHE_CUBIC_SPLINE == (int)SPLINE2_CUBIC &&
                   (int)LATHE_QUADRATIC_SPLINE == (int)SPLINE2_QUADRATIC,
               "lathe's splines are spline2's");

/* The piece from the control points p (as many as the spline needs). */
static struct lseg make_seg(enum lathe_spline kind, const double (*p)[2])
{
	struct lseg s;
	memset(&s, 0, sizeof s);
	double lo[2], hi[2];
	s.deg = spline2_piece((enum spline2_kind)kind, p, s.r, s.y, lo, hi);
	s.rlo = lo[0], s.rhi = hi[0];
	s.ylo = lo[1], s.yhi = hi[1];
	return s;
}

/* out = a * b for polynomials of degrees na and nb (ascending). */
static void pmul(const double *a, int na, const double *b, int nb, double *out)
{
	for (int i = 0; i <= na + nb; i++)
		out[i] = 0;
	for (int i = 0; i <= na; i++)
		for (int j = 0; j <= nb; j++)
			out[i + j] += a[i] * b[j];
}

typedef bool (*hit_sink)(void *ctx, double t, int part, double u);

/* Every hit with tmin < t < tmax, passed to take in no order; stops when
 * take returns false. */
static void lathe_hits(const struct lathe *L, const struct ray *r, double tmin, double tmax, hit_sink take, void *ctx)
{
	vec3 o = r->org, d = r->dir;
	/* x^2 + z^2 along the ray: A t^2 + B t + C. */
	double A = d.x * d.x + d.z * d.z, B = 2 * (o.x * d.x + o.z * d.z), C = o.x * o.x + o.z * o.z;
	/* The bounding cylinder: the ray's nearest approach to the axis. */
	if (A > 0) {
		double tc = -B / (2 * A), dist2 = C - B * B / (4 * A);
		(void)tc;
		if (dist2 > L->rmax * L->rmax * (1 + 1e-12))
			return;
	} else if (C > L->rmax * L->rmax * (1 + 1e-12)) {
		return;
	}
	for (int i = 0; i < L->nseg; i++) {
		const struct lseg *s = &L->seg[i];
		/* The piece's slab of heights along the ray. */
		if (d.y != 0) {
			double ta = (s->ylo - o.y) / d.y, tb = (s->yhi - o.y) / d.y;
			double lo = fmin(ta, tb), hi = fmax(ta, tb);
			if (hi < tmin - 1e-9 * fabs(tmin) || lo > tmax)
				continue;
		} else if (o.y < s->ylo || o.y > s->yhi) {
			continue;
		}
		double roots[6];
		int nr;
		if (d.y != 0) {
			/* A (y(u) - oy)^2 + B dy (y(u) - oy) + C dy^2 - dy^2 r(u)^2 = 0 */
			double e[4] = {s->y[0] - o.y, s->y[1], s->y[2], s->y[3]};
			double e2[7], r2[7], q[7];
			pmul(e, s->deg, e, s->deg, e2);
			pmul(s->r, s->deg, s->r, s->deg, r2);
			int deg = 2 * s->deg;
			double dy2 = d.y * d.y;
			for (int k = 0; k <= deg; k++)
				q[k] = A * e2[k] - dy2 * r2[k] + (k <= s->deg ? B * d.y * e[k] : 0);
			q[0] += C * dy2;
			nr = solve_poly(q, deg, -1e-9, 1 + 1e-9, L->sturm, roots);
			for (int k = 0; k < nr; k++) {
				double u = fmin(fmax(roots[k], 0), 1);
				double yu = spline2_at(s->y, u), t = (yu - o.y) / d.y;
				if (A > 0 && fabs(d.y) * fabs(d.y) < 0.25 * A) {
					/* A shallow ray: t from the radius is better conditioned. */
					double ru = spline2_at(s->r, u), tt[2];
					int n2 = solve_quadratic(A, B, C - ru * ru, tt);
					double best = INFINITY;
					for (int j = 0; j < n2; j++) {
						double err = fabs(o.y + tt[j] * d.y - yu);
						if (err < best) {
							best = err;
							t = tt[j];
						}
					}
				}
				if (t > tmin && t < tmax && !take(ctx, t, i, u))
					return;
			}
		} else {
			double e[4] = {s->y[0] - o.y, s->y[1], s->y[2], s->y[3]};
			nr = solve_poly(e, s->deg, -1e-9, 1 + 1e-9, L->sturm, roots);
			for (int k = 0; k < nr; k++) {
				double u = fmin(fmax(roots[k], 0), 1);
				double ru = spline2_at(s->r, u), tt[2];
				int n2 = solve_quadratic(A, B, C - ru * ru, tt);
				for (int j = 0; j < n2; j++)
					if (tt[j] > tmin && tt[j] < tmax && !take(ctx, tt[j], i, u))
						return;
			}
		}
	}
}

static bool lathe_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hit_closest c = {.found = false};
	lathe_hits((const struct lathe *)o, r, tmin, tmax, hit_take_closest, &c);
	if (!c.found)
		return false;
	h->t = c.t;
	h->part = c.part;
	h->u = c.u;
	return true;
}

static int lathe_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                          int max)
{
	struct hit_all a = {.o = o, .out = out, .max = max};
	lathe_hits((const struct lathe *)o, r, tmin, tmax, hit_take_all, &a);
	return a.n;
}

/* Crossings of the half-line from (R, y) towards +r; a crossing at a joint
 * counts for the piece that leaves it upwards or arrives at it downwards,
 * so a joint where the curve only touches the half-line counts twice or
 * not at all. */
static bool lathe_inside(const struct object *o, vec3 p)
{
	const struct lathe *L = (const struct lathe *)o;
	double R = sqrt(p.x * p.x + p.z * p.z), y = p.y;
	if (!(y >= L->ylo && y <= L->yhi && R <= L->rmax))
		return false;
	int count = 0;
	const double eps = 1e-9;
	for (int i = 0; i < L->nseg; i++) {
		const struct lseg *s = &L->seg[i];
		if (y < s->ylo || y > s->yhi || R > s->rhi)
			continue;
		double c[4] = {s->y[0] - y, s->y[1], s->y[2], s->y[3]}, rt[3];
		int nr = solve_poly(c, s->deg, -eps, 1 + eps, false, rt);
		for (int k = 0; k < nr; k++) {
			double u = fmin(fmax(rt[k], 0), 1);
			if (!(spline2_at(s->r, u) > R))
				continue;
			double dy = spline2_slope(s->y, u);
			if ((dy > 0 && rt[k] < 1 - eps) || (dy < 0 && rt[k] > eps))
				count++;
		}
	}
	return count & 1;
}

static vec3 lathe_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct lathe *L = (const struct lathe *)o;
	if (h->part < 0 || h->part >= L->nseg)
		return v3(0, 1, 0);
	const struct lseg *s = &L->seg[h->part];
	double dr = spline2_slope(s->r, h->u), dy = spline2_slope(s->y, h->u);
	double R = sqrt(p.x * p.x + p.z * p.z);
	vec3 n = R > 0 ? v3(dy * p.x / R, -dr, dy * p.z / R) : v3(0, dr > 0 ? -1 : 1, 0);
	if (n.x == 0 && n.y == 0 && n.z == 0)
		return v3(0, 1, 0);
	return n;
}

static struct aabb lathe_bounds(const struct object *o)
{
	const struct lathe *L = (const struct lathe *)o;
	return (struct aabb){v3(-L->rmax, L->ylo, -L->rmax), v3(L->rmax, L->yhi, L->rmax)};
}

/* POV-Ray's uv: u the angle about y from +x towards... see doc/objects.md:
 * u = atan2(z, x) / 2 pi wrapped to [0, 1), v the position along the
 * curve, (piece + u) / pieces. */
static bool lathe_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	const struct lathe *L = (const struct lathe *)o;
	double a = atan2(p.z, p.x) / (2 * M_PI);
	if (a < 0)
		a += 1;
	uv[0] = a;
	uv[1] = L->nseg > 0 && h->part >= 0 ? (h->part + h->u) / L->nseg : 0;
	return true;
}

static struct object *lathe_copy(const struct object *o)
{
	const struct lathe *L = (const struct lathe *)o;
	struct lathe *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *L;
	c->seg = malloc((size_t)(L->nseg ? L->nseg : 1) * sizeof *c->seg);
	if (!c->seg) abort();
	memcpy(c->seg, L->seg, (size_t)L->nseg * sizeof *c->seg);
	return &c->base;
}

static void lathe_destroy(struct object *o)
{
	free(((struct lathe *)o)->seg);
}

static const struct object_ops lathe_ops = {
	.name = "lathe",
	.intersect = lathe_intersect,
	.all_hits = lathe_all_hits,
	.inside = lathe_inside,
	.normal = lathe_normal,
	.bounds = lathe_bounds,
	.uv = lathe_uv,
	.copy = lathe_copy,
	.destroy = lathe_destroy,
};

struct object *lathe_new(enum lathe_spline spline, const double (*pts)[2], int n, struct srcpos pos)
{
	struct lathe *L = calloc(1, sizeof *L);
	if (!L) abort();
	object_init(&L->base, &lathe_ops, pos);
	int first, count, step = 1;
	switch (spline) {
	case LATHE_LINEAR_SPLINE: first = 0; count = n - 1; break;
	case LATHE_QUADRATIC_SPLINE: first = 0; count = n - 2; break;
	case LATHE_CUBIC_SPLINE: first = 0; count = n - 3; break;
	default: first = 0; count = n / 4; step = 4; break;
	}
	if (count < 0)
		count = 0;
	L->seg = malloc((size_t)(count ? count : 1) * sizeof *L->seg);
	if (!L->seg) abort();
	L->nseg = count;
	L->rmax = 0;
	L->ylo = INFINITY;
	L->yhi = -INFINITY;
	for (int i = 0; i < count; i++) {
		struct lseg s = make_seg(spline, pts + first + i * step);
		L->seg[i] = s;
		L->rmax = fmax(L->rmax, fmax(fabs(s.rlo), fabs(s.rhi)));
		L->ylo = fmin(L->ylo, s.ylo);
		L->yhi = fmax(L->yhi, s.yhi);
	}
	if (count == 0)
		L->ylo = L->yhi = 0;
	return &L->base;
}

void lathe_set_sturm(struct object *o, bool sturm)
{
	((struct lathe *)o)->sturm = sturm;
}

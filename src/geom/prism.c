/* prism.c: prism { spline sweep h1, h2, n, points [open] [sturm] }: closed
 * curves in the xz plane swept along y from h1 to h2, unchanged
 * (linear_sweep) or scaled by y (conic_sweep: the points given are the
 * cross-section at y = 1, the apex is the origin). Where an even number of
 * sub-prisms overlap there is a hole (the even-odd rule).
 *
 * Every piece of curve is kept as a polynomial in u on [0, 1] of degree 1
 * to 3 (x(u), z(u)). The curves are POV-Ray's, measured with trace() to
 * eight digits:
 * - linear_spline: the straight line between two points;
 * - quadratic_spline: the parabola through P[i-1], P[i], P[i+1] at
 *   u = -1, 0, 1, drawn from P[i] to P[i+1];
 * - cubic_spline: Catmull-Rom, the Hermite cubic from P[i] to P[i+1] with
 *   tangents (P[i+1] - P[i-1]) / 2 and (P[i+2] - P[i]) / 2;
 * - bezier_spline: the cubic Bezier curve of each four points.
 *
 * A ray meets the side where it crosses a curve: for a linear sweep the
 * ray's projection on the xz plane is a line a x + b z + c = 0, for a conic
 * sweep the points (x/y, z/y) of the ray are on such a line too, so in both
 * cases the side hits are the roots in [0, 1] of a x(u) + b z(u) + c, a
 * polynomial of the curve's degree. The caps are the planes y = h1 and
 * y = h2 inside the cross-section there.
 *
 * Normals are POV-Ray's raw ones (what its trace() returns): the side's
 * normal points to the right of the curve's direction of travel (outward
 * for a counter-clockwise curve seen from +y, inward for a clockwise one),
 * the other way for bezier_spline, and both caps give +y. The renderer
 * turns every normal to face the ray, so only trace() sees the sign. */
#include "geom/shapes.h"
#include "geom/solve.h"
#include "geom/spline2.h"
#include "geom/collect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One piece of curve: x(u) = x[0] + x[1] u + x[2] u^2 + x[3] u^3, the
 * same for z, u in [0, 1]. */
struct pseg {
	double x[4], z[4];
	int deg;             /* 1..3 */
	double lo[2], hi[2]; /* the piece's extent in x and z */
};

enum { PART_BOTTOM = -1, PART_TOP = -2 };

struct prism {
	struct object base;
	struct pseg *seg;
	int nseg;
	double h1, h2;       /* h1 <= h2 */
	bool conic;          /* conic_sweep */
	bool bezier;         /* normals point the other way */
	bool open;           /* no caps */
	bool sturm;
	double lo[2], hi[2]; /* the cross-section's extent (at y = 1 for conic) */
};

_Static_assert((int)PRISM_BEZIER_SPLINE == (int)SPLINE2_BEZIER && (int)PRISM_CUBIC_SPLINE == (int)SPLINE2_CUBIC &&
                   (int)PRISM_QUADRATIC_SPLINE == (int)SPLINE2_QUADRATIC,
               "prism's splines are spline2's");

/* The piece of the given spline from its control points p (2, 3 or 4
 * points as the spline needs; see spline2.h). */
static struct pseg make_seg(enum prism_spline kind, const double (*p)[2])
{
	struct pseg s;
	memset(&s, 0, sizeof s);
	s.deg = spline2_piece((enum spline2_kind)kind, p, s.x, s.z, s.lo, s.hi);
	return s;
}

static bool same_point(const double *a, const double *b)
{
	return a[0] == b[0] && a[1] == b[1];
}

/* The pieces made so far, and the extent of every piece made, kept or
 * not (POV-Ray's bounds count the pieces it ignores). */
struct cutter {
	struct pseg *seg;
	int n, cap;
	double lo[2], hi[2];
};

/* Append the piece made from p. */
static void push_seg(struct cutter *c, enum prism_spline kind, const double (*p)[2])
{
	if (c->n == c->cap) {
		c->cap = c->cap ? c->cap * 2 : 16;
		c->seg = realloc(c->seg, (size_t)c->cap * sizeof *c->seg);
		if (!c->seg) abort();
	}
	struct pseg s = make_seg(kind, p);
	for (int k = 0; k < 2; k++) {
		c->lo[k] = fmin(c->lo[k], s.lo[k]);
		c->hi[k] = fmax(c->hi[k], s.hi[k]);
	}
	c->seg[c->n++] = s;
}

/* Cut the points into sub-prisms and those into pieces, with POV-Ray's
 * rules (the manual's, and its behaviour where the manual is silent):
 * - linear: a sub-prism ends at the point equal to its first; the last one
 *   is closed if it is not (rep->closed_last).
 * - quadratic: a control point, the start S, more points, S again.
 * - cubic: a control point, S, more points, S again, a control point.
 * - bezier: groups of four (start, two controls, end); each group must
 *   start where the previous ended, and a sub-prism ends at a group that
 *   ends at its first start. A sub-prism that breaks off or never closes is
 *   dropped (rep->dropped counts them).
 * A single point left over at the end is ignored. A quadratic or cubic
 * sub-prism of more points that is not closed when the points run out is
 * an error: rep->open_at is the index of its first point (else -1), and
 * nothing is kept. */
static void cut(enum prism_spline kind, const double (*p)[2], int n, struct cutter *c, struct prism_report *rep)
{
	switch (kind) {
	case PRISM_LINEAR_SPLINE: {
		int i = 0;
		while (i < n) {
			int s = i, j = i + 1;
			while (j < n && !same_point(p[j], p[s]))
				j++;
			if (j < n) { /* closed by p[j] */
				for (int k = s; k < j; k++)
					push_seg(c, kind, p + k);
				i = j + 1;
				continue;
			}
			if (n - s >= 2) { /* the last one, closed here */
				rep->closed_last = true;
				for (int k = s; k < n - 1; k++)
					push_seg(c, kind, p + k);
				double last[2][2] = {{p[n - 1][0], p[n - 1][1]}, {p[s][0], p[s][1]}};
				push_seg(c, kind, (const double (*)[2])last);
			}
			break;
		}
		break;
	}
	case PRISM_QUADRATIC_SPLINE:
	case PRISM_CUBIC_SPLINE: {
		int extra = kind == PRISM_CUBIC_SPLINE; /* the end control point */
		int i = 0;
		while (i < n - 1) {
			int s = i + 1, j = s + 1; /* p[i] is the control point, p[s] the start */
			while (j < n && !same_point(p[j], p[s]))
				j++;
			if (j + extra >= n) {
				rep->open_at = i;
				c->n = 0;
				return;
			}
			for (int k = s; k < j; k++)
				push_seg(c, kind, p + k - 1);
			i = j + 1 + extra;
		}
		break;
	}
	case PRISM_BEZIER_SPLINE: {
		int first = 0, start = 0;
		bool open = false;
		for (int i = 0; i + 3 < n; i += 4) {
			if (open && !same_point(p[i], p[i - 1])) {
				/* A break: the sub-prism so far never closes. */
				rep->dropped++;
				c->n = first;
				open = false;
			}
			if (!open) {
				first = c->n;
				start = i;
				open = true;
			}
			push_seg(c, kind, p + i);
			if (same_point(p[i + 3], p[start]))
				open = false;
		}
		if (open) {
			rep->dropped++;
			c->n = first;
		}
		break;
	}
	}
}

/* Is the point (x, z) inside the cross-section (the even-odd rule)? The
 * crossings of the half-line from it towards +x are counted; a crossing
 * at a joint between two pieces counts for the piece that leaves it
 * upwards (z growing) or arrives at it downwards, so that a joint where
 * the curve only touches the half-line counts twice or not at all. */
static bool inside_2d(const struct prism *P, double x, double z)
{
	if (!(x >= P->lo[0] && x <= P->hi[0] && z >= P->lo[1] && z <= P->hi[1]))
		return false;
	int count = 0;
	const double eps = 1e-9;
	for (int i = 0; i < P->nseg; i++) {
		const struct pseg *s = &P->seg[i];
		if (z < s->lo[1] || z > s->hi[1] || x > s->hi[0])
			continue;
		double c[4] = {s->z[0] - z, s->z[1], s->z[2], s->z[3]}, r[3];
		int nr = solve_poly(c, s->deg, -eps, 1 + eps, false, r);
		for (int k = 0; k < nr; k++) {
			double u = fmin(fmax(r[k], 0), 1);
			if (!(spline2_at(s->x, u) > x))
				continue;
			double dz = spline2_slope(s->z, u);
			if ((dz > 0 && r[k] < 1 - eps) || (dz < 0 && r[k] > eps))
				count++;
		}
	}
	return count & 1;
}

/* The cross-section point of (x, y, z): itself for a linear sweep, scaled
 * back to y = 1 for a conic one; false where there is none (y = 0). */
static bool section_point(const struct prism *P, vec3 p, double *x, double *z)
{
	if (!P->conic) {
		*x = p.x;
		*z = p.z;
		return true;
	}
	if (p.y == 0)
		return false;
	*x = p.x / p.y;
	*z = p.z / p.y;
	return true;
}

/* Every hit with tmin < t < tmax, passed to `take` in no order; stops
 * early when take returns false. */
typedef bool (*hit_sink)(void *ctx, double t, int part, double u);

static void prism_hits(const struct prism *P, const struct ray *r, double tmin, double tmax, hit_sink take, void *ctx)
{
	vec3 o = r->org, d = r->dir;
	/* Where the ray is between the caps. */
	double y0 = -INFINITY, y1 = INFINITY;
	if (d.y != 0) {
		double a = (P->h1 - o.y) / d.y, b = (P->h2 - o.y) / d.y;
		y0 = fmin(a, b);
		y1 = fmax(a, b);
	} else if (o.y < P->h1 || o.y > P->h2) {
		return;
	}
	double lo = fmax(tmin, y0), hi = fmin(tmax, y1);
	if (!(lo <= hi))
		return;

	/* Caps. */
	if (!P->open && d.y != 0) {
		for (int c = 0; c < 2; c++) {
			double h = c == 0 ? P->h1 : P->h2;
			double t = (h - o.y) / d.y;
			if (!(t > tmin && t < tmax))
				continue;
			vec3 q = v3_madd(o, d, t);
			q.y = h;
			double x, z;
			if (section_point(P, q, &x, &z) && inside_2d(P, x, z))
				if (!take(ctx, t, c == 0 ? PART_BOTTOM : PART_TOP, 0))
					return;
		}
	}

	/* Sides: the line a X + b Z + c = 0 the ray's points satisfy. */
	double a, b, c;
	if (P->conic) {
		a = o.y * d.z - o.z * d.y;
		b = o.x * d.y - o.y * d.x;
	} else {
		a = d.z;
		b = -d.x;
	}
	c = o.z * d.x - o.x * d.z;
	if (a == 0 && b == 0)
		return; /* a linear-sweep ray along y, or one through a conic's apex along a generator */
	for (int i = 0; i < P->nseg; i++) {
		const struct pseg *s = &P->seg[i];
		/* Skip a piece whose extent lies on one side of the line. */
		double f00 = a * s->lo[0] + b * s->lo[1] + c, f01 = a * s->lo[0] + b * s->hi[1] + c;
		double f10 = a * s->hi[0] + b * s->lo[1] + c, f11 = a * s->hi[0] + b * s->hi[1] + c;
		if ((f00 > 0 && f01 > 0 && f10 > 0 && f11 > 0) || (f00 < 0 && f01 < 0 && f10 < 0 && f11 < 0))
			continue;
		double q[4], roots[3];
		for (int k = 0; k < 4; k++)
			q[k] = a * s->x[k] + b * s->z[k];
		q[0] += c;
		int nr = solve_poly(q, s->deg, -1e-9, 1 + 1e-9, P->sturm, roots);
		for (int k = 0; k < nr; k++) {
			double u = fmin(fmax(roots[k], 0), 1);
			double X = spline2_at(s->x, u), Z = spline2_at(s->z, u);
			double t;
			if (P->conic) {
				double ex = d.x - d.y * X, ez = d.z - d.y * Z;
				if (fabs(ex) >= fabs(ez))
					t = (o.y * X - o.x) / ex;
				else
					t = (o.y * Z - o.z) / ez;
			} else {
				t = fabs(d.x) >= fabs(d.z) ? (X - o.x) / d.x : (Z - o.z) / d.z;
			}
			double y = o.y + t * d.y;
			if (!(t > tmin && t < tmax) || !(y >= P->h1 && y <= P->h2))
				continue;
			if (!take(ctx, t, i, u))
				return;
		}
	}
}

static bool prism_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hit_closest c = {.found = false};
	prism_hits((const struct prism *)o, r, tmin, tmax, hit_take_closest, &c);
	if (!c.found)
		return false;
	h->t = c.t;
	h->part = c.part;
	h->u = c.u;
	return true;
}

static int prism_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	struct hit_all a = {.o = o, .out = out, .max = max};
	prism_hits((const struct prism *)o, r, tmin, tmax, hit_take_all, &a);
	return a.n;
}

/* Between the heights and inside the cross-section there (an open prism
 * has the same inside as a closed one, as in POV-Ray). */
static bool prism_inside(const struct object *o, vec3 p)
{
	const struct prism *P = (const struct prism *)o;
	if (!(p.y >= P->h1 && p.y <= P->h2))
		return false;
	double x, z;
	return section_point(P, p, &x, &z) && inside_2d(P, x, z);
}

static vec3 prism_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct prism *P = (const struct prism *)o;
	(void)p;
	if (h->part < 0 || h->part >= P->nseg)
		return v3(0, 1, 0);
	const struct pseg *s = &P->seg[h->part];
	double u = h->u;
	double X = spline2_at(s->x, u), Z = spline2_at(s->z, u);
	double dx = spline2_slope(s->x, u), dz = spline2_slope(s->z, u);
	vec3 n = v3(dz, P->conic ? Z * dx - X * dz : 0, -dx);
	if (P->bezier)
		n = v3_neg(n);
	if (n.x == 0 && n.y == 0 && n.z == 0)
		return v3(0, 1, 0);
	return n;
}

static struct aabb prism_bounds(const struct object *o)
{
	const struct prism *P = (const struct prism *)o;
	if (!(P->lo[0] <= P->hi[0]))
		return (struct aabb){v3(0, P->h1, 0), v3(0, P->h2, 0)}; /* no pieces */
	if (!P->conic)
		return (struct aabb){v3(P->lo[0], P->h1, P->lo[1]), v3(P->hi[0], P->h2, P->hi[1])};
	/* The cross-section at y is the one at 1 scaled by y. */
	double lo[2], hi[2];
	for (int k = 0; k < 2; k++) {
		double v[4] = {P->h1 * P->lo[k], P->h1 * P->hi[k], P->h2 * P->lo[k], P->h2 * P->hi[k]};
		lo[k] = fmin(fmin(v[0], v[1]), fmin(v[2], v[3]));
		hi[k] = fmax(fmax(v[0], v[1]), fmax(v[2], v[3]));
	}
	return (struct aabb){v3(lo[0], P->h1, lo[1]), v3(hi[0], P->h2, hi[1])};
}

static struct object *prism_copy(const struct object *o)
{
	const struct prism *P = (const struct prism *)o;
	struct prism *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *P;
	c->seg = malloc((size_t)(P->nseg ? P->nseg : 1) * sizeof *c->seg);
	if (!c->seg) abort();
	memcpy(c->seg, P->seg, (size_t)P->nseg * sizeof *c->seg);
	return &c->base;
}

static void prism_destroy(struct object *o)
{
	free(((struct prism *)o)->seg);
}

static const struct object_ops prism_ops = {
	.name = "prism",
	.intersect = prism_intersect,
	.all_hits = prism_all_hits,
	.inside = prism_inside,
	.normal = prism_normal,
	.bounds = prism_bounds,
	.copy = prism_copy,
	.destroy = prism_destroy,
};

struct object *prism_new(enum prism_spline spline, bool conic, double h1, double h2, const double (*pts)[2], int n,
                         struct srcpos pos, struct prism_report *rep)
{
	struct prism_report local;
	if (!rep)
		rep = &local;
	memset(rep, 0, sizeof *rep);
	rep->open_at = -1;
	struct prism *P = calloc(1, sizeof *P);
	if (!P) abort();
	object_init(&P->base, &prism_ops, pos);
	P->h1 = fmin(h1, h2);
	P->h2 = fmax(h1, h2);
	P->conic = conic;
	P->bezier = spline == PRISM_BEZIER_SPLINE;
	struct cutter c = {.lo = {INFINITY, INFINITY}, .hi = {-INFINITY, -INFINITY}};
	cut(spline, pts, n, &c, rep);
	P->seg = c.seg;
	P->nseg = c.n;
	for (int k = 0; k < 2; k++) {
		P->lo[k] = c.lo[k];
		P->hi[k] = c.hi[k];
	}
	return &P->base;
}

void prism_set_open(struct object *o, bool open)
{
	((struct prism *)o)->open = open;
}

void prism_set_sturm(struct object *o, bool sturm)
{
	((struct prism *)o)->sturm = sturm;
}

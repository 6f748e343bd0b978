/* sor.c: sor { n, points [open] [sturm] }: a surface of revolution about
 * the y axis whose squared radius is, on each piece j (between points j
 * and j + 1, j = 1 .. n - 3), the cubic r^2 = A h^3 + B h^2 + C h + D
 * that passes through both points with the slopes of r^2 the manual gives,
 * 2 r(j) (r(j+1) - r(j-1)) / (h(j+1) - h(j-1)) and
 * 2 r(j+1) (r(j+2) - r(j)) / (h(j+2) - h(j)). Unless open, discs close it
 * at the first and last height (the caps).
 *
 * Along a ray o + t d, x^2 + z^2 is a quadratic in t and r^2 a cubic in y,
 * so each piece's hits are the roots of a cubic in t, taken between the
 * piece's heights. The normal is the gradient of x^2 + z^2 - r^2(y), which
 * points out of the solid (as POV-Ray's trace() reports it, whichever side
 * the ray comes from); the caps give -y and +y. The bounds are the
 * cylinder of the largest radius the pieces reach. */
#include "geom/shapes2.h"
#include "geom/solve.h"
#include "geom/collect.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { PART_BOTTOM = -1, PART_TOP = -2 };

struct sseg {
	double c[4];  /* r^2 = c[0] + c[1] h + c[2] h^2 + c[3] h^3 */
	double h0, h1;
};

struct sor {
	struct object base;
	struct sseg *seg;
	int nseg;
	bool open, sturm;
	double rmax;
	double r2lo, r2hi; /* squared radii of the caps */
};

static double cubic_at(const double c[4], double h)
{
	return ((c[3] * h + c[2]) * h + c[1]) * h + c[0];
}

static double dcubic_at(const double c[4], double h)
{
	return (3 * c[3] * h + 2 * c[2]) * h + c[1];
}

/* Solve the 4x4 system m x = b by Gaussian elimination with partial
 * pivoting; false if it is singular. */
static bool solve4(double m[4][4], double b[4], double x[4])
{
	for (int col = 0; col < 4; col++) {
		int piv = col;
		for (int r = col + 1; r < 4; r++)
			if (fabs(m[r][col]) > fabs(m[piv][col]))
				piv = r;
		if (m[piv][col] == 0)
			return false;
		if (piv != col) {
			for (int k = 0; k < 4; k++) {
				double tmp = m[col][k];
				m[col][k] = m[piv][k];
				m[piv][k] = tmp;
			}
			double tb = b[col];
			b[col] = b[piv];
			b[piv] = tb;
		}
		for (int r = col + 1; r < 4; r++) {
			double f = m[r][col] / m[col][col];
			for (int k = col; k < 4; k++)
				m[r][k] -= f * m[col][k];
			b[r] -= f * b[col];
		}
	}
	for (int r = 3; r >= 0; r--) {
		double s = b[r];
		for (int k = r + 1; k < 4; k++)
			s -= m[r][k] * x[k];
		x[r] = s / m[r][r];
	}
	return true;
}

/* The crossings go to a collector of geom/collect.h (u unused: 0). */
typedef bool (*hit_sink)(void *ctx, double t, int part, double u);

static void sor_hits(const struct sor *S, const struct ray *r, double tmin, double tmax, hit_sink take, void *ctx)
{
	if (S->nseg == 0)
		return;
	vec3 o = r->org, d = r->dir;
	double A = d.x * d.x + d.z * d.z, B = 2 * (o.x * d.x + o.z * d.z), C = o.x * o.x + o.z * o.z;
	double ylo = S->seg[0].h0, yhi = S->seg[S->nseg - 1].h1;
	/* The bounding cylinder. */
	double rr = S->rmax * S->rmax * (1 + 1e-12);
	if (A > 0 ? C - B * B / (4 * A) > rr : C > rr)
		return;
	if (d.y == 0 && (o.y < ylo || o.y > yhi))
		return;
	/* Caps. */
	if (!S->open && d.y != 0) {
		for (int c = 0; c < 2; c++) {
			double h = c == 0 ? ylo : yhi, t = (h - o.y) / d.y;
			if (!(t > tmin && t < tmax))
				continue;
			double x = o.x + t * d.x, z = o.z + t * d.z;
			if (x * x + z * z <= (c == 0 ? S->r2lo : S->r2hi))
				if (!take(ctx, t, c == 0 ? PART_BOTTOM : PART_TOP, 0))
					return;
		}
	}
	for (int i = 0; i < S->nseg; i++) {
		const struct sseg *s = &S->seg[i];
		double lo = tmin, hi = tmax;
		if (d.y != 0) {
			double ta = (s->h0 - o.y) / d.y, tb = (s->h1 - o.y) / d.y;
			lo = fmax(lo, fmin(ta, tb));
			hi = fmin(hi, fmax(ta, tb));
			if (!(lo <= hi))
				continue;
		} else if (o.y < s->h0 || o.y > s->h1) {
			continue;
		}
		/* r^2(o.y + t d.y) as a cubic in t: expand about o.y. */
		double y0 = o.y, dy = d.y;
		double p0 = cubic_at(s->c, y0), p1 = dcubic_at(s->c, y0);
		double p2 = s->c[2] + 3 * s->c[3] * y0;
		double p3 = s->c[3];
		double q[4] = {C - p0, B - p1 * dy, A - p2 * dy * dy, -p3 * dy * dy * dy};
		double roots[3];
		/* Widen the interval a little so a root on a joint is not lost;
		 * heights are checked again below. */
		double w = 1e-9 * fmax(1, fmax(fabs(lo), fabs(hi)));
		int nr = solve_poly(q, 3, lo - w, hi + w, S->sturm, roots);
		for (int k = 0; k < nr; k++) {
			double t = roots[k];
			if (!(t > tmin && t < tmax))
				continue;
			double y = o.y + t * d.y;
			if (y < s->h0 || y > s->h1)
				continue;
			if (!take(ctx, t, i, 0))
				return;
		}
	}
}

static bool sor_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hit_closest c = {.found = false};
	sor_hits((const struct sor *)o, r, tmin, tmax, hit_take_closest, &c);
	if (!c.found)
		return false;
	h->t = c.t;
	h->part = c.part;
	return true;
}

static int sor_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                        int max)
{
	struct hit_all a = {.o = o, .out = out, .max = max};
	sor_hits((const struct sor *)o, r, tmin, tmax, hit_take_all, &a);
	return a.n;
}

/* The piece whose heights hold y, or -1. */
static int piece_at(const struct sor *S, double y)
{
	for (int i = 0; i < S->nseg; i++)
		if (y >= S->seg[i].h0 && y <= S->seg[i].h1)
			return i;
	return -1;
}

/* Between the caps and within the radius there (open or not, as in
 * POV-Ray). */
static bool sor_inside(const struct object *o, vec3 p)
{
	const struct sor *S = (const struct sor *)o;
	int i = piece_at(S, p.y);
	if (i < 0)
		return false;
	return p.x * p.x + p.z * p.z < cubic_at(S->seg[i].c, p.y);
}

static vec3 sor_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct sor *S = (const struct sor *)o;
	if (h->part == PART_BOTTOM)
		return v3(0, -1, 0);
	if (h->part == PART_TOP || h->part < 0 || h->part >= S->nseg)
		return v3(0, 1, 0);
	vec3 n = v3(p.x, -0.5 * dcubic_at(S->seg[h->part].c, p.y), p.z);
	if (n.x == 0 && n.y == 0 && n.z == 0)
		return v3(0, 1, 0);
	return n;
}

static struct aabb sor_bounds(const struct object *o)
{
	const struct sor *S = (const struct sor *)o;
	if (S->nseg == 0)
		return (struct aabb){v3(0, 0, 0), v3(0, 0, 0)};
	double ylo = S->seg[0].h0, yhi = S->seg[S->nseg - 1].h1;
	return (struct aabb){v3(-S->rmax, ylo, -S->rmax), v3(S->rmax, yhi, S->rmax)};
}

/* uv: u the angle about y (see doc/objects.md), v the height's fraction of
 * the object's; the caps map the disc's radius. */
static bool sor_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	const struct sor *S = (const struct sor *)o;
	(void)h;
	double a = atan2(p.z, p.x) / (2 * M_PI);
	if (a < 0)
		a += 1;
	uv[0] = a;
	double ylo = S->nseg ? S->seg[0].h0 : 0, yhi = S->nseg ? S->seg[S->nseg - 1].h1 : 1;
	uv[1] = yhi > ylo ? (p.y - ylo) / (yhi - ylo) : 0;
	return true;
}

static struct object *sor_copy(const struct object *o)
{
	const struct sor *S = (const struct sor *)o;
	struct sor *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *S;
	c->seg = malloc((size_t)(S->nseg ? S->nseg : 1) * sizeof *c->seg);
	if (!c->seg) abort();
	memcpy(c->seg, S->seg, (size_t)S->nseg * sizeof *c->seg);
	return &c->base;
}

static void sor_destroy(struct object *o)
{
	free(((struct sor *)o)->seg);
}

static const struct object_ops sor_ops = {
	.name = "sor",
	.intersect = sor_intersect,
	.all_hits = sor_all_hits,
	.inside = sor_inside,
	.normal = sor_normal,
	.bounds = sor_bounds,
	.uv = sor_uv,
	.copy = sor_copy,
	.destroy = sor_destroy,
};

int sor_check(const double (*pts)[2], int n)
{
	for (int i = 2; i <= n - 2; i++)
		if (!(pts[i][1] > pts[i - 1][1]))
			return i;
	return -1;
}

/* The largest value of the cubic c on [h0, h1]. */
static double cubic_max(const double c[4], double h0, double h1)
{
	double m = fmax(cubic_at(c, h0), cubic_at(c, h1)), r[2];
	int n = solve_quadratic(3 * c[3], 2 * c[2], c[1], r);
	for (int i = 0; i < n; i++)
		if (r[i] > h0 && r[i] < h1)
			m = fmax(m, cubic_at(c, r[i]));
	return m;
}

struct object *sor_new(const double (*pts)[2], int n, struct srcpos pos)
{
	struct sor *S = calloc(1, sizeof *S);
	if (!S) abort();
	object_init(&S->base, &sor_ops, pos);
	int count = n >= 4 ? n - 3 : 0;
	S->seg = malloc((size_t)(count ? count : 1) * sizeof *S->seg);
	if (!S->seg) abort();
	S->nseg = count;
	double r2max = 0;
	for (int j = 1; j <= count; j++) {
		struct sseg *s = &S->seg[j - 1];
		double h0 = pts[j][1], h1 = pts[j + 1][1];
		double r0 = pts[j][0], r1 = pts[j + 1][0];
		double m[4][4] = {
			{1, h0, h0 * h0, h0 * h0 * h0},
			{1, h1, h1 * h1, h1 * h1 * h1},
			{0, 1, 2 * h0, 3 * h0 * h0},
			{0, 1, 2 * h1, 3 * h1 * h1},
		};
		double b[4] = {r0 * r0, r1 * r1, 2 * r0 * (r1 - pts[j - 1][0]) / (h1 - pts[j - 1][1]),
		               2 * r1 * (pts[j + 2][0] - r0) / (pts[j + 2][1] - h0)};
		if (!solve4(m, b, s->c))
			memset(s->c, 0, sizeof s->c);
		s->h0 = h0;
		s->h1 = h1;
		r2max = fmax(r2max, cubic_max(s->c, h0, h1));
	}
	S->rmax = sqrt(r2max);
	if (count) {
		S->r2lo = pts[1][0] * pts[1][0];
		S->r2hi = pts[count + 1][0] * pts[count + 1][0];
	}
	return &S->base;
}

void sor_set_open(struct object *o, bool open)
{
	((struct sor *)o)->open = open;
}

void sor_set_sturm(struct object *o, bool sturm)
{
	((struct sor *)o)->sturm = sturm;
}

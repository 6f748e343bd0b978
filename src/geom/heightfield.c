/* heightfield.c: height_field { image | function W, H { ... } [smooth]
 * [water_level L] [hierarchy B] } (heightfield.h).
 *
 * The samples lie on a W x H grid over the unit square: column c at
 * x = c / (W - 1), image row r at z = 1 - r / (H - 1) (the image's top row
 * at the back), each height a 16-bit value over 65536. Each square of four
 * samples is two triangles split along the diagonal from (c + 1, z) to
 * (c, z + 1). Rays walk the grid's squares in order (a 2-D DDA in grid
 * units, where the squares are unit squares), testing the two triangles
 * of each. There are no sides or bottom: the surface is the triangles
 * only, and the inside is below them, down to minus infinity.
 *
 * What POV-Ray does and lucent follows (measured with trace(), inside(),
 * min_extent and max_extent):
 *  - the bounds are x and z in [0, 1], y from the larger of the lowest
 *    height and the water level to the highest height (swapped when the
 *    water is above every height);
 *  - with water_level, hits whose height is below the level are not
 *    reported (a point rule: f = x with water 0.4 is hit at x = 0.41, not
 *    at 0.38);
 *  - crossings nearer than 1e-4 to the ray's origin, along the world ray,
 *    are not reported (a point 7e-5 above the surface sees no hit, one
 *    1e-4 above sees it). */
#include "geom/heightfield.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HF_MIN_DEPTH 1e-4

struct hfield {
	struct object base;
	int w, h;              /* samples along x and z */
	double *y;             /* w * h heights, y[j * w + i]: x = i / (w - 1), z = j / (h - 1) */
	double ymin, ymax;
	double water;
	bool smooth, hierarchy;
};

static struct hfield *hf_of(const struct object *o)
{
	return (struct hfield *)o;
}

static double at(const struct hfield *F, int i, int j)
{
	return F->y[(size_t)j * (size_t)F->w + (size_t)i];
}

uint16_t heightfield_quantize(double f)
{
	double v = f * 65535;
	if (!(v > -2147483648.0 && v < 2147483648.0))
		return 0;
	return (uint16_t)((unsigned)(int)v & 0xffffu);
}

/* The ray against triangle (a, b, c) in grid space: t and the
 * barycentrics of b and c; false if it misses. Edges count (a ray through
 * a shared edge finds either triangle). */
static bool tri_hit(vec3 o, vec3 d, vec3 a, vec3 b, vec3 c, double *t, double *u, double *v)
{
	vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a);
	vec3 p = v3_cross(d, e2);
	double det = v3_dot(e1, p);
	if (det == 0)
		return false;
	double inv = 1 / det;
	vec3 s = v3_sub(o, a);
	double uu = v3_dot(s, p) * inv;
	const double eps = 1e-12;
	if (uu < -eps || uu > 1 + eps)
		return false;
	vec3 q = v3_cross(s, e1);
	double vv = v3_dot(d, q) * inv;
	if (vv < -eps || uu + vv > 1 + eps)
		return false;
	*t = v3_dot(e2, q) * inv;
	*u = uu;
	*v = vv;
	return true;
}

/* The corners of triangle k (0 or 1) of square (i, j), in grid space. */
static void tri_of(const struct hfield *F, int i, int j, int k, vec3 p[3])
{
	if (k == 0) {
		p[0] = v3(i, at(F, i, j), j);
		p[1] = v3(i + 1, at(F, i + 1, j), j);
		p[2] = v3(i, at(F, i, j + 1), j + 1);
	} else {
		p[0] = v3(i + 1, at(F, i + 1, j), j);
		p[1] = v3(i + 1, at(F, i + 1, j + 1), j + 1);
		p[2] = v3(i, at(F, i, j + 1), j + 1);
	}
}

typedef bool (*hf_sink)(void *ctx, double t, int part, double u, double v);

/* Report the crossings in (tmin, tmax), square by square along the ray
 * (in increasing t between squares; within one square in any order), to
 * take, which returns whether to go on. With first_only the walk ends
 * with the first square that has a crossing (the nearest is there). */
static void hf_hits(const struct object *o, const struct ray *r, double tmin, double tmax, bool first_only,
                    hf_sink take, void *ctx)
{
	const struct hfield *F = hf_of(o);
	double sx = F->w - 1, sz = F->h - 1;
	vec3 go = v3(r->org.x * sx, r->org.y, r->org.z * sz);
	vec3 gd = v3(r->dir.x * sx, r->dir.y, r->dir.z * sz);
	double wlen = o->has_xf ? v3_len(mat_dir(&o->xf.fwd, r->dir)) : v3_len(r->dir);
	if (!(wlen > 0))
		return;
	tmin = fmax(tmin, HF_MIN_DEPTH / wlen);
	/* Clip to the box of the samples. */
	double lo[3] = {0, fmax(F->ymin, F->water), 0}, hi[3] = {sx, F->ymax, sz};
	double oo[3] = {go.x, go.y, go.z}, dd[3] = {gd.x, gd.y, gd.z};
	double t0 = tmin, t1 = tmax;
	for (int k = 0; k < 3; k++) {
		if (dd[k] != 0) {
			double ta = (lo[k] - oo[k]) / dd[k], tb = (hi[k] - oo[k]) / dd[k];
			t0 = fmax(t0, fmin(ta, tb));
			t1 = fmin(t1, fmax(ta, tb));
		} else if (oo[k] < lo[k] || oo[k] > hi[k]) {
			return;
		}
	}
	/* A little slack so that rays along the top or the sides are kept. */
	double slack = 1e-9 * (1 + fabs(t0) + fabs(t1));
	if (!(t0 <= t1 + slack))
		return;
	/* The walk over the squares. */
	double px = go.x + t0 * gd.x, pz = go.z + t0 * gd.z;
	int i = (int)floor(px), j = (int)floor(pz);
	i = i < 0 ? 0 : i > F->w - 2 ? F->w - 2 : i;
	j = j < 0 ? 0 : j > F->h - 2 ? F->h - 2 : j;
	int si = gd.x > 0 ? 1 : gd.x < 0 ? -1 : 0, sj = gd.z > 0 ? 1 : gd.z < 0 ? -1 : 0;
	double tnx = si ? ((si > 0 ? i + 1 : i) - go.x) / gd.x : INFINITY;
	double tnz = sj ? ((sj > 0 ? j + 1 : j) - go.z) / gd.z : INFINITY;
	double dtx = si ? fabs(1 / gd.x) : INFINITY, dtz = sj ? fabs(1 / gd.z) : INFINITY;
	double tin = t0;
	for (;;) {
		double tout = fmin(fmin(tnx, tnz), t1);
		/* Skip a square whose heights the ray passes above or below. */
		double ya = go.y + tin * gd.y, yb = go.y + tout * gd.y;
		double c00 = at(F, i, j), c10 = at(F, i + 1, j), c01 = at(F, i, j + 1), c11 = at(F, i + 1, j + 1);
		double cmin = fmin(fmin(c00, c10), fmin(c01, c11)), cmax = fmax(fmax(c00, c10), fmax(c01, c11));
		double rmin = fmin(ya, yb), rmax = fmax(ya, yb), e = 1e-9 * (1 + fabs(rmin) + fabs(rmax));
		bool found = false;
		if (rmin <= cmax + e && rmax >= cmin - e) {
			for (int k = 0; k < 2; k++) {
				vec3 p[3];
				tri_of(F, i, j, k, p);
				double t, u, v;
				if (!tri_hit(go, gd, p[0], p[1], p[2], &t, &u, &v))
					continue;
				if (!(t > tmin && t < tmax))
					continue;
				if (F->water > 0 && go.y + t * gd.y < F->water)
					continue;
				int part = ((j * (F->w - 1)) + i) * 2 + k;
				found = true;
				if (!take(ctx, t, part, u, v))
					return;
			}
		}
		if (tout >= t1 || (found && first_only))
			return;
		if (tnx < tnz) {
			i += si;
			tin = tnx;
			tnx += dtx;
			if (i < 0 || i > F->w - 2)
				return;
		} else {
			j += sj;
			tin = tnz;
			tnz += dtz;
			if (j < 0 || j > F->h - 2)
				return;
		}
	}
}

struct hf_first {
	double t, u, v;
	int part;
	bool found;
};

static bool take_first(void *ctx, double t, int part, double u, double v)
{
	struct hf_first *f = ctx;
	if (!f->found || t < f->t) {
		f->t = t;
		f->part = part;
		f->u = u;
		f->v = v;
		f->found = true;
	}
	return true;
}

static bool hf_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hf_first f = {.found = false};
	hf_hits(o, r, tmin, tmax, true, take_first, &f);
	if (!f.found)
		return false;
	h->t = f.t;
	h->part = f.part;
	h->u = f.u;
	h->v = f.v;
	return true;
}

struct hf_all {
	const struct object *o;
	struct hit *out;
	int n, max;
};

static bool take_all(void *ctx, double t, int part, double u, double v)
{
	struct hf_all *a = ctx;
	/* Keep them sorted, dropping a crossing found twice (on an edge). */
	for (int k = 0; k < a->n; k++)
		if (fabs(a->out[k].t - t) <= 1e-12 * (1 + fabs(t)))
			return true;
	if (a->n == a->max && t >= a->out[a->n - 1].t)
		return true;
	int k = a->n < a->max ? a->n++ : a->n - 1;
	while (k > 0 && a->out[k - 1].t > t) {
		a->out[k] = a->out[k - 1];
		k--;
	}
	a->out[k] = (struct hit){.t = t, .obj = a->o, .part = part, .u = u, .v = v};
	return true;
}

static int hf_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                       int max)
{
	struct hf_all a = {o, out, 0, max};
	if (max <= 0)
		return 0;
	hf_hits(o, r, tmin, tmax, false, take_all, &a);
	return a.n;
}

/* The surface's height over grid point (gx, gz), on the triangle there. */
static double height_at(const struct hfield *F, double gx, double gz)
{
	int i = (int)floor(gx), j = (int)floor(gz);
	i = i < 0 ? 0 : i > F->w - 2 ? F->w - 2 : i;
	j = j < 0 ? 0 : j > F->h - 2 ? F->h - 2 : j;
	double fx = gx - i, fz = gz - j;
	if (fx + fz <= 1)
		return at(F, i, j) + fx * (at(F, i + 1, j) - at(F, i, j)) + fz * (at(F, i, j + 1) - at(F, i, j));
	return at(F, i + 1, j + 1) + (1 - fx) * (at(F, i, j + 1) - at(F, i + 1, j + 1)) +
	       (1 - fz) * (at(F, i + 1, j) - at(F, i + 1, j + 1));
}

/* Over the unit square and below the surface (measured: POV-Ray's inside
 * reaches down without end). */
static bool hf_inside(const struct object *o, vec3 p)
{
	const struct hfield *F = hf_of(o);
	if (!(p.x >= 0 && p.x <= 1 && p.z >= 0 && p.z <= 1))
		return false;
	return p.y < height_at(F, p.x * (F->w - 1), p.z * (F->h - 1));
}

/* The smooth normal at grid point (i, j), object space: the central
 * differences of the heights (one-sided at the borders). */
static vec3 vertex_normal(const struct hfield *F, int i, int j)
{
	int i0 = i > 0 ? i - 1 : i, i1 = i < F->w - 1 ? i + 1 : i;
	int j0 = j > 0 ? j - 1 : j, j1 = j < F->h - 1 ? j + 1 : j;
	double gx = (at(F, i1, j) - at(F, i0, j)) / ((double)(i1 - i0) / (F->w - 1));
	double gz = (at(F, i, j1) - at(F, i, j0)) / ((double)(j1 - j0) / (F->h - 1));
	return v3_norm(v3(-gx, 1, -gz));
}

static vec3 hf_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct hfield *F = hf_of(o);
	(void)p;
	int cells = (F->w - 1) * (F->h - 1);
	if (h->part < 0 || h->part >= 2 * cells)
		return v3(0, 1, 0);
	int k = h->part & 1, c = h->part >> 1;
	int i = c % (F->w - 1), j = c / (F->w - 1);
	if (F->smooth) {
		static const int corner[2][3][2] = {{{0, 0}, {1, 0}, {0, 1}}, {{1, 0}, {1, 1}, {0, 1}}};
		double w[3] = {1 - h->u - h->v, h->u, h->v};
		vec3 n = v3(0, 0, 0);
		for (int m = 0; m < 3; m++)
			n = v3_madd(n, vertex_normal(F, i + corner[k][m][0], j + corner[k][m][1]), w[m]);
		return n;
	}
	vec3 q[3];
	tri_of(F, i, j, k, q);
	vec3 n = v3_cross(v3_sub(q[2], q[0]), v3_sub(q[1], q[0]));
	/* Grid space to object space: x and z scaled by 1 / (w - 1) and
	 * 1 / (h - 1); normals by the inverse. */
	n = v3(n.x * (F->w - 1), n.y, n.z * (F->h - 1));
	return n.y < 0 ? v3_neg(n) : n;
}

static struct aabb hf_bounds(const struct object *o)
{
	const struct hfield *F = hf_of(o);
	double lo = fmax(F->ymin, F->water), hi = F->ymax;
	if (lo > hi) {
		double t = lo;
		lo = hi;
		hi = t;
	}
	return (struct aabb){v3(0, lo, 0), v3(1, hi, 1)};
}

static struct object *hf_copy(const struct object *o)
{
	const struct hfield *F = hf_of(o);
	struct hfield *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *F;
	size_t n = (size_t)F->w * (size_t)F->h;
	c->y = malloc(n * sizeof *c->y);
	if (!c->y) abort();
	memcpy(c->y, F->y, n * sizeof *c->y);
	return &c->base;
}

static void hf_destroy(struct object *o)
{
	free(hf_of(o)->y);
}

static const struct object_ops hf_ops = {
	.name = "height_field",
	.intersect = hf_intersect,
	.all_hits = hf_all_hits,
	.inside = hf_inside,
	.normal = hf_normal,
	.bounds = hf_bounds,
	.copy = hf_copy,
	.destroy = hf_destroy,
};

struct object *heightfield_new(int w, int h, const uint16_t *v, struct srcpos pos)
{
	struct hfield *F = calloc(1, sizeof *F);
	if (!F) abort();
	object_init(&F->base, &hf_ops, pos);
	F->w = w;
	F->h = h;
	F->hierarchy = true;
	size_t n = (size_t)w * (size_t)h;
	F->y = malloc(n * sizeof *F->y);
	if (!F->y) abort();
	F->ymin = INFINITY;
	F->ymax = -INFINITY;
	for (int r = 0; r < h; r++)
		for (int c = 0; c < w; c++) {
			double y = v[(size_t)r * (size_t)w + (size_t)c] / 65536.0;
			F->y[(size_t)(h - 1 - r) * (size_t)w + (size_t)c] = y;
			F->ymin = fmin(F->ymin, y);
			F->ymax = fmax(F->ymax, y);
		}
	return &F->base;
}

void heightfield_set_smooth(struct object *o, bool smooth)
{
	hf_of(o)->smooth = smooth;
}

void heightfield_set_water_level(struct object *o, double level)
{
	hf_of(o)->water = level;
}

void heightfield_set_hierarchy(struct object *o, bool on)
{
	hf_of(o)->hierarchy = on;
}

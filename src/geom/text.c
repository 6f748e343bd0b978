/* text.c: text { ttf FONT STRING THICKNESS, OFFSET }: the glyphs of a
 * TrueType font laid out along +x with the baseline on y = 0 and extruded
 * from z = 0 to z = THICKNESS; one unit is the font's em.
 *
 * The layout is POV-Ray 3.7's, measured with min_extent, max_extent and
 * trace() on its own fonts: each glyph stands at the pen position, the pen
 * moves by the glyph's advance width, the kerning of the pair (the font's
 * kern table) and OFFSET's x and y (OFFSET's z is ignored); the whole line
 * is moved left by the first glyph's xMin (its glyph header's, which need
 * not be its left side bearing), so its ink starts at x = 0. The bounds
 * are the outlines' and, for an empty glyph (a space), its pen position;
 * a text of no characters is unbounded.
 *
 * Every glyph outline is a set of closed contours made of quadratic Bezier
 * pieces and lines. A ray meets the sides where its projection on the xy
 * plane, a line a x + b y + c = 0, crosses a piece: a root in [0, 1] of a
 * polynomial of degree 2 or 1. The caps are the planes z = 0 and
 * z = THICKNESS inside the outline (the even-odd rule). Normals are POV-Ray's
 * raw ones: a side's normal points to the right of the contour's direction
 * of travel (inward for TrueType's clockwise outer contours); the cap at
 * z = 0 gives -z and the one at z = THICKNESS gives +z, whatever the sign
 * of THICKNESS. The renderer turns normals to face the ray, so only
 * trace() sees the sign. */
#include "geom/shapes.h"
#include "geom/solve.h"

#include "font/ttf.h"
#include "geom/collect.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One piece: x(u) = x[0] + x[1] u + x[2] u^2, the same for y, u in [0, 1]. */
struct tseg {
	double x[3], y[3];
	double lo[2], hi[2]; /* its extent in x and y */
};

/* One glyph: the outline src placed at (dx, dy), which becomes the pieces
 * seg[first, first + n) of the text. */
struct tglyph {
	struct ttf_shared_outline *src; /* a reference */
	double dx, dy;
	int first, n;
	double lo[2], hi[2];
	double reach_lo[2], reach_hi[2]; /* the box widened by a little, for
	                                  * glyph_in_reach: a hit's point is worked
	                                  * out from its piece and may round past it */
};

enum { PART_FRONT = -1, PART_BACK = -2 };

/* The pieces are made from the glyphs' shared outlines when the text is
 * prepared (or first traced or tested, at parse time): shapes.inc's
 * Text_Width measures a text of every prefix of a string (Circle_Text:
 * 11,000 glyphs for 150 letters), and a text that is only measured never
 * needs them. */
struct text {
	struct object base;
	struct tseg *seg;    /* nseg pieces, or NULL until made */
	int nseg;
	struct tglyph *glyph;
	int nglyph;
	double scale;        /* em units per font unit */
	double z0, z1;       /* z0 <= z1 */
	double zfront;       /* 0: the cap whose normal is -z */
	double lo[2], hi[2]; /* the extent of every glyph */
};

static double poly2(const double c[3], double u)
{
	return (c[2] * u + c[1]) * u + c[0];
}

static double dpoly2(const double c[3], double u)
{
	return 2 * c[2] * u + c[1];
}

/* The extent of c(u) for u in [0, 1]. */
static void extent(const double c[3], double *lo, double *hi)
{
	double a = c[0], b = poly2(c, 1);
	*lo = fmin(a, b);
	*hi = fmax(a, b);
	if (c[2] != 0) {
		double u = -c[1] / (2 * c[2]);
		if (u > 0 && u < 1) {
			double v = poly2(c, u);
			*lo = fmin(*lo, v);
			*hi = fmax(*hi, v);
		}
	}
}

/* Glyph g's pieces are made from its outline scaled by T->scale and moved
 * by (g->dx, g->dy); its boxes are those of the pieces. */
static void make_seg(const struct ttf_piece *p, double s, double dx, double dy, struct tseg *q)
{
	double x0 = p->x0 * s + dx, y0 = p->y0 * s + dy, x1 = p->x1 * s + dx, y1 = p->y1 * s + dy;
	double cx = p->cx * s + dx, cy = p->cy * s + dy;
	if (p->line) {
		q->x[0] = x0, q->x[1] = x1 - x0, q->x[2] = 0;
		q->y[0] = y0, q->y[1] = y1 - y0, q->y[2] = 0;
	} else {
		/* (1-u)^2 P0 + 2u(1-u) C + u^2 P1 */
		q->x[0] = x0, q->x[1] = 2 * (cx - x0), q->x[2] = x0 - 2 * cx + x1;
		q->y[0] = y0, q->y[1] = 2 * (cy - y0), q->y[2] = y0 - 2 * cy + y1;
	}
	extent(q->x, &q->lo[0], &q->hi[0]);
	extent(q->y, &q->lo[1], &q->hi[1]);
}

static void make_pieces(struct text *T)
{
	T->seg = malloc((size_t)T->nseg * sizeof *T->seg);
	if (!T->seg) abort();
	for (int k = 0; k < T->nglyph; k++) {
		const struct tglyph *g = &T->glyph[k];
		for (int i = 0; i < g->n; i++)
			make_seg(&g->src->ol.p[i], T->scale, g->dx, g->dy, &T->seg[g->first + i]);
	}
}

/* The pieces, made on first need. prepare makes them before a render, so
 * that only parse-time callers (trace(), inside(), one thread) may come
 * here with a text whose pieces are not made yet. */
static const struct tseg *pieces(const struct text *T)
{
	if (!T->seg && T->nseg)
		make_pieces((struct text *)T);
	return T->seg;
}

/* ---- intersection ---- */

/* Is (x, y) inside glyph g (the even-odd rule)? The half-line towards +x
 * is followed; a crossing at a joint between two pieces counts for the
 * piece that leaves it upwards or arrives at it downwards, so that a
 * joint where the outline only touches the half-line counts twice or not
 * at all. */
static bool inside_glyph(const struct tseg *seg, const struct tglyph *g, double x, double y)
{
	if (!(x >= g->lo[0] && x <= g->hi[0] && y >= g->lo[1] && y <= g->hi[1]))
		return false;
	const double eps = 1e-9;
	int count = 0;
	for (int i = g->first; i < g->first + g->n; i++) {
		const struct tseg *s = &seg[i];
		if (y < s->lo[1] || y > s->hi[1] || x > s->hi[0])
			continue;
		double r[2];
		int nr = solve_quadratic(s->y[2], s->y[1], s->y[0] - y, r);
		for (int k = 0; k < nr; k++) {
			if (!(r[k] >= -eps && r[k] <= 1 + eps))
				continue;
			double u = fmin(fmax(r[k], 0), 1);
			if (!(poly2(s->x, u) > x))
				continue;
			double dy = dpoly2(s->y, u);
			if ((dy > 0 && r[k] < 1 - eps) || (dy < 0 && r[k] > eps))
				count++;
		}
	}
	return count & 1;
}

static bool inside_2d(const struct text *T, double x, double y)
{
	if (!(x >= T->lo[0] && x <= T->hi[0] && y >= T->lo[1] && y <= T->hi[1]))
		return false;
	/* Glyphs may overlap (a negative offset, kerning): inside one is
	 * inside the text. */
	const struct tseg *seg = pieces(T);
	for (int i = 0; i < T->nglyph; i++)
		if (inside_glyph(seg, &T->glyph[i], x, y))
			return true;
	return false;
}

/* Every hit with tmin < t < tmax, passed to `take` in no order; stops
 * early when take returns false. With `closest`, only the nearest hit
 * matters: each hit lowers tmax, and the glyphs are taken in the ray's
 * direction along x and skipped where their boxes lie beyond it (a ray
 * along a line of 150 letters tested every piece of every letter). */
typedef bool (*hit_sink)(void *ctx, double t, int part, double u);

/* Narrow [*lo, *hi] to where the ray o + t d is inside the box [blo, bhi]
 * in x and y; false when a ray parallel to an axis is outside it. */
static bool clip_box2(const double blo[2], const double bhi[2], vec3 o, vec3 d, double *lo, double *hi)
{
	double oo[2] = {o.x, o.y}, dd[2] = {d.x, d.y};
	for (int k = 0; k < 2; k++) {
		if (dd[k] != 0) {
			double a = (blo[k] - oo[k]) / dd[k], b = (bhi[k] - oo[k]) / dd[k];
			*lo = fmax(*lo, fmin(a, b));
			*hi = fmin(*hi, fmax(a, b));
		} else if (oo[k] < blo[k] || oo[k] > bhi[k]) {
			return false;
		}
	}
	return true;
}

/* Does the ray reach glyph g for some t in [lo, hi] (with a little slack)? */
static bool glyph_in_reach(const struct tglyph *g, vec3 o, vec3 d, double lo, double hi)
{
	if (!clip_box2(g->reach_lo, g->reach_hi, o, d, &lo, &hi))
		return false;
	return lo <= hi + 1e-9 * (fabs(lo) + fabs(hi) + 1);
}

/* Does the box [lo, hi] in x and y lie wholly on one side of the line
 * a X + b Y + c = 0? Then nothing in it meets the line. */
static bool off_line(const double lo[2], const double hi[2], double a, double b, double c)
{
	double f00 = a * lo[0] + b * lo[1] + c, f01 = a * lo[0] + b * hi[1] + c;
	double f10 = a * hi[0] + b * lo[1] + c, f11 = a * hi[0] + b * hi[1] + c;
	return (f00 > 0 && f01 > 0 && f10 > 0 && f11 > 0) || (f00 < 0 && f01 < 0 && f10 < 0 && f11 < 0);
}

static void text_hits(const struct text *T, const struct ray *r, double tmin, double tmax, hit_sink take, void *ctx,
                      bool closest)
{
	if (T->nglyph == 0)
		return;
	vec3 o = r->org, d = r->dir;
	/* Where the ray is between the caps. */
	double lo = tmin, hi = tmax;
	if (d.z != 0) {
		double a = (T->z0 - o.z) / d.z, b = (T->z1 - o.z) / d.z;
		lo = fmax(lo, fmin(a, b));
		hi = fmin(hi, fmax(a, b));
	} else if (o.z < T->z0 || o.z > T->z1) {
		return;
	}
	/* And inside the text's box in x and y. */
	if (!clip_box2(T->lo, T->hi, o, d, &lo, &hi) || !(lo <= hi))
		return;

	/* Caps. */
	if (d.z != 0) {
		for (int c = 0; c < 2; c++) {
			double z = c == 0 ? T->z0 : T->z1;
			double t = (z - o.z) / d.z;
			if (!(t > tmin && t < tmax))
				continue;
			if (inside_2d(T, o.x + t * d.x, o.y + t * d.y)) {
				if (!take(ctx, t, z == T->zfront ? PART_FRONT : PART_BACK, 0))
					return;
				if (closest && t < tmax)
					tmax = t;
			}
		}
	}

	/* Sides: the line a X + b Y + c = 0 the ray's points satisfy. */
	double a = d.y, b = -d.x, c = o.y * d.x - o.x * d.y;
	if (a == 0 && b == 0)
		return; /* a ray along z */
	const struct tseg *seg = pieces(T);
	for (int step = 0; step < T->nglyph; step++) {
		const struct tglyph *g = &T->glyph[closest && d.x < 0 ? T->nglyph - 1 - step : step];
		if (closest && !glyph_in_reach(g, o, d, lo, fmin(hi, tmax)))
			continue;
		if (off_line(g->lo, g->hi, a, b, c))
			continue;
		for (int i = g->first; i < g->first + g->n; i++) {
			const struct tseg *s = &seg[i];
			if (off_line(s->lo, s->hi, a, b, c))
				continue;
			double q[3] = {a * s->x[0] + b * s->y[0] + c, a * s->x[1] + b * s->y[1], a * s->x[2] + b * s->y[2]};
			double roots[2];
			int nr = solve_quadratic(q[2], q[1], q[0], roots);
			for (int k = 0; k < nr; k++) {
				if (!(roots[k] >= -1e-9 && roots[k] <= 1 + 1e-9))
					continue;
				double u = fmin(fmax(roots[k], 0), 1);
				double X = poly2(s->x, u), Y = poly2(s->y, u);
				double t = fabs(d.x) >= fabs(d.y) ? (X - o.x) / d.x : (Y - o.y) / d.y;
				double z = o.z + t * d.z;
				if (!(t > tmin && t < tmax) || !(z >= T->z0 && z <= T->z1))
					continue;
				if (!take(ctx, t, i, u))
					return;
				if (closest)
					tmax = t;
			}
		}
	}
}

static bool text_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct hit_closest c = {.found = false};
	text_hits((const struct text *)o, r, tmin, tmax, hit_take_closest, &c, true);
	if (!c.found)
		return false;
	h->t = c.t;
	h->part = c.part;
	h->u = c.u;
	return true;
}

static int text_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	struct hit_all a = {.o = o, .out = out, .max = max};
	text_hits((const struct text *)o, r, tmin, tmax, hit_take_all, &a, false);
	return a.n;
}

static bool text_inside(const struct object *o, vec3 p)
{
	const struct text *T = (const struct text *)o;
	return p.z >= T->z0 && p.z <= T->z1 && inside_2d(T, p.x, p.y);
}

static vec3 text_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct text *T = (const struct text *)o;
	(void)p;
	if (h->part == PART_FRONT)
		return v3(0, 0, -1);
	if (h->part < 0 || h->part >= T->nseg)
		return v3(0, 0, 1);
	const struct tseg *s = &pieces(T)[h->part];
	double dx = dpoly2(s->x, h->u), dy = dpoly2(s->y, h->u);
	if (dx == 0 && dy == 0)
		return v3(0, 0, 1);
	return v3(dy, -dx, 0);
}

static struct aabb text_bounds(const struct object *o)
{
	const struct text *T = (const struct text *)o;
	if (!(T->lo[0] <= T->hi[0])) /* no characters: unbounded, as in POV-Ray */
		return (struct aabb){v3(-INFINITY, -INFINITY, -INFINITY), v3(INFINITY, INFINITY, INFINITY)};
	return (struct aabb){v3(T->lo[0], T->lo[1], T->z0), v3(T->hi[0], T->hi[1], T->z1)};
}

/* POV-Ray's box: the outlines' box, 1e-6 deeper at each face, turned by
 * rotate <0.001, 0.001, 0.001>, and that box moved by the object's
 * transform (not the two as one matrix: "Hi" rotated <20,30,40> reaches
 * x = -0.329250, the box of the turned box, not -0.329225). Measured with
 * min_extent/max_extent on timrom.ttf: "I" of thickness 1 (ink [0,0.296]
 * x [0,0.68]) gives x in [-0.0000118680, 0.2960174680] = [-0.68 s,
 * 0.296 + 1.000001 s] with s = sin 0.001 degrees, and z in
 * [-0.0000061662, 1.0000128746] = [-1e-6 - 0.296 s, 1 + 1e-6 + 0.68 s]; a
 * thickness of 2 or 3 doubles or triples the part from z. */
static struct aabb text_world_bounds(const struct object *o)
{
	const struct text *T = (const struct text *)o;
	struct aabb b = text_bounds(o);
	if (!aabb_is_finite(b))
		return b;
	b.lo.z = fmin(T->z0, T->z1) - 1e-6;
	b.hi.z = fmax(T->z0, T->z1) + 1e-6;
	struct xform tilt = xform_rotate(v3(0.001, 0.001, 0.001));
	b = mat_bounds(&tilt.fwd, b);
	/* Kept in single precision before it moves (text { ... rotate
	 * <20,30,10> } reaches z = 1.0199735165 from the rounded box,
	 * 1.0199733973 from the exact one). */
	return o->has_xf ? mat_bounds(&o->xf.fwd, object_box_single(b)) : b;
}

static struct object *text_copy(const struct object *o)
{
	const struct text *T = (const struct text *)o;
	struct text *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *T;
	c->glyph = malloc((T->nglyph ? (size_t)T->nglyph : 1) * sizeof *c->glyph);
	if (!c->glyph) abort();
	for (int i = 0; i < T->nglyph; i++) {
		c->glyph[i] = T->glyph[i];
		ttf_outline_ref(c->glyph[i].src);
	}
	c->seg = NULL;
	if (T->seg) {
		c->seg = malloc((size_t)T->nseg * sizeof *c->seg);
		if (!c->seg) abort();
		memcpy(c->seg, T->seg, (size_t)T->nseg * sizeof *c->seg);
	}
	return &c->base;
}

static void text_destroy(struct object *o)
{
	struct text *T = (struct text *)o;
	for (int i = 0; i < T->nglyph; i++)
		ttf_outline_release(T->glyph[i].src);
	free(T->seg);
	free(T->glyph);
}

static void text_prepare(struct object *o)
{
	pieces((const struct text *)o);
}

static const struct object_ops text_ops = {
	.name = "text",
	.intersect = text_intersect,
	.all_hits = text_all_hits,
	.inside = text_inside,
	.normal = text_normal,
	.bounds = text_bounds,
	.world_bounds = text_world_bounds,
	.prepare = text_prepare,
	.copy = text_copy,
	.destroy = text_destroy,
};

/* ---- building ---- */

/* Append glyph outline src (the reference passes to T) at (dx, dy) to T:
 * its boxes now, its pieces when they are needed. */
static void add_glyph(struct text *T, struct ttf_shared_outline *src, double dx, double dy)
{
	const struct ttf_outline *ol = &src->ol;
	if ((size_t)T->nseg + ol->n > INT_MAX) abort();
	struct tglyph *g = &T->glyph[T->nglyph++];
	g->src = src;
	g->dx = dx;
	g->dy = dy;
	g->first = T->nseg;
	g->n = (int)ol->n;
	T->nseg += g->n;
	g->lo[0] = g->lo[1] = INFINITY;
	g->hi[0] = g->hi[1] = -INFINITY;
	for (size_t i = 0; i < ol->n; i++) {
		struct tseg q;
		make_seg(&ol->p[i], T->scale, dx, dy, &q);
		for (int k = 0; k < 2; k++) {
			g->lo[k] = fmin(g->lo[k], q.lo[k]);
			g->hi[k] = fmax(g->hi[k], q.hi[k]);
		}
	}
	for (int k = 0; k < 2; k++) {
		double e = 1e-7 * (fabs(g->lo[k]) + fabs(g->hi[k]) + 1);
		g->reach_lo[k] = g->lo[k] - e;
		g->reach_hi[k] = g->hi[k] + e;
		T->lo[k] = fmin(T->lo[k], g->lo[k]);
		T->hi[k] = fmax(T->hi[k], g->hi[k]);
	}
}

struct object *text_new(struct ttf_font *font, const uint32_t *codes, size_t n, double thickness, double off_x,
                        double off_y, struct srcpos pos, uint32_t *bad_glyph)
{
	struct text *T = calloc(1, sizeof *T);
	if (!T) abort();
	object_init(&T->base, &text_ops, pos);
	T->z0 = fmin(0, thickness);
	T->z1 = fmax(0, thickness);
	T->zfront = 0;
	T->lo[0] = T->lo[1] = INFINITY;
	T->hi[0] = T->hi[1] = -INFINITY;
	if (bad_glyph)
		*bad_glyph = 0;
	double s = 1.0 / ttf_units_per_em(font);
	T->scale = s;
	T->glyph = malloc((n ? n : 1) * sizeof *T->glyph);
	if (!T->glyph) abort();
	double pen_x = 0, pen_y = 0;
	unsigned prev = 0;
	for (size_t i = 0; i < n; i++) {
		unsigned g = ttf_glyph_index(font, codes[i]);
		struct ttf_metrics m;
		struct ttf_shared_outline *src = NULL;
		if (!ttf_glyph_metrics(font, g, &m) || !(src = ttf_glyph_shared(font, g))) {
			if (bad_glyph && !*bad_glyph)
				*bad_glyph = codes[i] & ~TTF_MAC ? codes[i] & ~TTF_MAC : 0xFFFFFFFFu;
			continue;
		}
		if (i == 0)
			pen_x = -m.xmin * s;
		else
			pen_x += ttf_kerning(font, prev, g) * s;
		if (src->ol.n) {
			/* POV-Ray 3.7 draws a composite glyph (an accented
			 * letter: a base and an accent placed on it) as if its
			 * xMin were min(xMin, 0): its xMin further right than a
			 * simple glyph when that is positive. Measured with
			 * DejaVuSans, DejaVuSerif and LiberationSans: "\u00e9"
			 * alone reaches 1151/2048 where "e" reaches
			 * (1151 - 113)/2048, "X\u00e9" is 113/2048 wider than
			 * "Xe", "\u00e9X" is as wide as "eX", and DejaVuSans'
			 * "\u00ef" (xMin -12) is placed as a simple glyph
			 * (tests/lang/text-composite). */
			double shift = m.composite && m.xmin > 0 ? m.xmin * s : 0;
			add_glyph(T, src, pen_x + shift, pen_y);
		} else {
			/* POV-Ray's bounds take in the pen position of an empty
			 * glyph (a space). */
			T->lo[0] = fmin(T->lo[0], pen_x);
			T->hi[0] = fmax(T->hi[0], pen_x);
			T->lo[1] = fmin(T->lo[1], pen_y);
			T->hi[1] = fmax(T->hi[1], pen_y);
			ttf_outline_release(src);
		}
		pen_x += m.advance * s + off_x;
		pen_y += off_y;
		prev = g;
	}
	/* POV-Ray's bounds begin at x = 0 even when the first glyph, a
	 * composite, is drawn right of it (measured: "\u00e9" in DejaVuSans). */
	if (n && T->lo[0] > 0)
		T->lo[0] = 0;
	return &T->base;
}

/* box.c: box { corner1, corner2 }, axis-aligned in object space. */
#include "geom/shapes.h"

#include <stdlib.h>

struct box {
	struct object base;
	vec3 lo, hi;
};

/* Slab test. Entry and exit parameters and the faces they cross
 * (part = 2*axis + (hi side ? 1 : 0)). A ray parallel to a slab and
 * outside it misses; inside it, that slab does not limit t. */
static bool slabs(const struct box *b, const struct ray *r, double *t0, double *t1, int *f0, int *f1)
{
	double tn = -INFINITY, tf = INFINITY;
	int fn = -1, ff = -1;
	for (int a = 0; a < 3; a++) {
		double o = v3_get(r->org, a), d = v3_get(r->dir, a);
		double lo = v3_get(b->lo, a), hi = v3_get(b->hi, a);
		if (d == 0) {
			if (o < lo || o > hi)
				return false;
			continue;
		}
		double inv = 1.0 / d;
		double ta = (lo - o) * inv, tb = (hi - o) * inv;
		int fa = 2 * a, fb = 2 * a + 1;
		if (ta > tb) {
			double tt = ta; ta = tb; tb = tt;
			int ft = fa; fa = fb; fb = ft;
		}
		if (ta > tn) { tn = ta; fn = fa; }
		if (tb < tf) { tf = tb; ff = fb; }
		if (tn > tf)
			return false;
	}
	*t0 = tn; *t1 = tf; *f0 = fn; *f1 = ff;
	return fn >= 0 || ff >= 0;
}

static bool box_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t0, t1;
	int f0, f1;
	if (!slabs((const struct box *)o, r, &t0, &t1, &f0, &f1))
		return false;
	if (f0 >= 0 && t0 > tmin && t0 < tmax) {
		h->t = t0;
		h->part = f0;
		return true;
	}
	if (f1 >= 0 && t1 > tmin && t1 < tmax) {
		h->t = t1;
		h->part = f1;
		return true;
	}
	return false;
}

static int box_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[2];
	int f[2], n = 0;
	if (!slabs((const struct box *)o, r, &t[0], &t[1], &f[0], &f[1]))
		return 0;
	for (int i = 0; i < 2 && n < max; i++)
		if (f[i] >= 0 && t[i] > tmin && t[i] < tmax) {
			out[n].t = t[i];
			out[n].part = f[i];
			out[n].obj = o;
			n++;
		}
	return n;
}

/* Points on the faces count as inside, as in POV-Ray (inside() of a point
 * on a face is 1, and a CSG keeps hits on another part's face: the boxes
 * of Segment_of_Object at 0 and 180 degrees meet along a face). A box
 * flat along an axis has no inside at all, where POV-Ray's has its whole
 * face: subtracting a set of zero volume must leave a solid as it was
 * (tests/stability degenerate.pov; POV-Ray leaves a black square there). */
static bool box_inside(const struct object *o, vec3 p)
{
	const struct box *b = (const struct box *)o;
	if (!(b->lo.x < b->hi.x && b->lo.y < b->hi.y && b->lo.z < b->hi.z))
		return false;
	return p.x >= b->lo.x && p.x <= b->hi.x && p.y >= b->lo.y && p.y <= b->hi.y &&
	       p.z >= b->lo.z && p.z <= b->hi.z;
}

static vec3 box_normal(const struct object *o, vec3 p, const struct hit *h)
{
	static const vec3 n[6] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
	if (h && h->part >= 0 && h->part < 6)
		return n[h->part];
	/* No hit record: the face nearest to p. */
	const struct box *b = (const struct box *)o;
	double best = INFINITY;
	int bi = 0;
	for (int a = 0; a < 3; a++) {
		double dl = fabs(v3_get(p, a) - v3_get(b->lo, a)), dh = fabs(v3_get(p, a) - v3_get(b->hi, a));
		if (dl < best) { best = dl; bi = 2 * a; }
		if (dh < best) { best = dh; bi = 2 * a + 1; }
	}
	return n[bi];
}

static struct aabb box_bounds(const struct object *o)
{
	const struct box *b = (const struct box *)o;
	return (struct aabb){b->lo, b->hi};
}

/* POV-Ray's box uv (measured against POV-Ray 3.7 renders): the six faces
 * are unfolded into a cross on a grid of 4 x 3 cells of the unit square,
 * each face filling one cell (1/4 wide, 1/3 high) whatever the box's
 * proportions:
 *
 *          u  0     1/4    1/2    3/4     1
 *   v 2/3..1         +y
 *   v 1/3..2/3   -x  +z     +x     -z
 *   v 0..1/3         -y
 *
 * Within its cell a face's u and v follow the box coordinates given in the
 * table below, each running 0..1 from the box's low to its high side or
 * the reverse; in POV-Ray's left-handed frame the four side faces read
 * u rightwards and v = +y upwards seen from inside the box (mirrored from
 * outside). The face is the hit's part, as for the normal, or the face
 * nearest p without one. */
static bool box_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	/* Per face (part = 2*axis + hi side): grid column and row, the axes
	 * that u and v follow, and whether each runs reversed. */
	static const struct { int col, row, ua, va; bool uflip, vflip; } cell[6] = {
		{0, 1, 2, 1, false, false}, /* -x */
		{2, 1, 2, 1, true, false},  /* +x */
		{1, 0, 0, 2, false, false}, /* -y */
		{1, 2, 0, 2, false, true},  /* +y */
		{3, 1, 0, 1, true, false},  /* -z */
		{1, 1, 0, 1, false, false}, /* +z */
	};
	const struct box *b = (const struct box *)o;
	vec3 n = box_normal(o, p, h);
	int axis = n.x != 0 ? 0 : n.y != 0 ? 1 : 2;
	int face = 2 * axis + (v3_get(n, axis) > 0);
	/* p's position across the box along axis a, clamped to [0,1] so that a
	 * point a rounding error off the face stays in its cell; 0 across a
	 * flat side (only the flat axis's own faces can be hit then). */
	double c[2];
	int ax[2] = {cell[face].ua, cell[face].va};
	bool flip[2] = {cell[face].uflip, cell[face].vflip};
	for (int i = 0; i < 2; i++) {
		double lo = v3_get(b->lo, ax[i]), size = v3_get(b->hi, ax[i]) - lo;
		double t = size > 0 ? (v3_get(p, ax[i]) - lo) / size : 0;
		t = t > 0 ? (t < 1 ? t : 1) : 0; /* also maps NaN to 0 */
		c[i] = flip[i] ? 1 - t : t;
	}
	uv[0] = (cell[face].col + c[0]) / 4;
	uv[1] = (cell[face].row + c[1]) / 3;
	return true;
}

static struct object *box_copy(const struct object *o)
{
	struct box *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct box *)o;
	return &c->base;
}

static const struct object_ops box_ops = {
	.name = "box",
	.intersect = box_intersect,
	.all_hits = box_all_hits,
	.inside = box_inside,
	.normal = box_normal,
	.bounds = box_bounds,
	.uv = box_uv,
	.copy = box_copy,
};

struct object *box_new(vec3 c1, vec3 c2, struct srcpos pos)
{
	struct box *b = calloc(1, sizeof *b);
	if (!b) abort();
	object_init(&b->base, &box_ops, pos);
	b->lo = v3_min(c1, c2);
	b->hi = v3_max(c1, c2);
	return &b->base;
}

/* bvh.c: binned-SAH bounding volume hierarchy (see bvh.h). */
#include "accel/bvh.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { BINS = 16, LEAF_MAX = 4, STACK_MAX = 64 };

struct bvh_node {
	struct aabb box;
	uint32_t first; /* leaf: first object index; inner: left child (right = left + 1) */
	uint32_t count; /* objects in a leaf; 0 for an inner node */
	uint32_t axis;  /* inner: split axis, for front-to-back order */
};

struct bvh {
	struct bvh_node *nodes;
	size_t nnodes, cap;
	const struct object **objs;
	size_t nobjs;
};

static uint32_t new_node(struct bvh *b)
{
	if (b->nnodes == b->cap) {
		b->cap = b->cap ? b->cap * 2 : 64;
		b->nodes = realloc(b->nodes, b->cap * sizeof *b->nodes);
		if (!b->nodes) abort();
	}
	memset(&b->nodes[b->nnodes], 0, sizeof b->nodes[0]);
	return (uint32_t)b->nnodes++;
}

/* What the build sorts: each object's bounds and centroid, kept together
 * so that the passes over them read memory in order. */
struct prim {
	struct aabb box;
	vec3 c;
	uint32_t idx; /* into the caller's array */
};

static inline double dmin(double a, double b) { return a < b ? a : b; }
static inline double dmax(double a, double b) { return a > b ? a : b; }

static inline void grow(struct aabb *a, const struct aabb *b)
{
	a->lo.x = dmin(a->lo.x, b->lo.x);
	a->lo.y = dmin(a->lo.y, b->lo.y);
	a->lo.z = dmin(a->lo.z, b->lo.z);
	a->hi.x = dmax(a->hi.x, b->hi.x);
	a->hi.y = dmax(a->hi.y, b->hi.y);
	a->hi.z = dmax(a->hi.z, b->hi.z);
}

static inline void grow_point(struct aabb *a, vec3 p)
{
	a->lo.x = dmin(a->lo.x, p.x);
	a->lo.y = dmin(a->lo.y, p.y);
	a->lo.z = dmin(a->lo.z, p.z);
	a->hi.x = dmax(a->hi.x, p.x);
	a->hi.y = dmax(a->hi.y, p.y);
	a->hi.z = dmax(a->hi.z, p.z);
}

/* The bin of a centroid coordinate v in [lo, lo + ext] (scale = BINS/ext). */
static inline int bin_of(double v, double lo, double scale)
{
	int k = (int)((v - lo) * scale);
	return k >= BINS ? BINS - 1 : k < 0 ? 0 : k;
}

/* Build the subtree over pr[first, first+n) into node `ni`. */
static void build(struct bvh *b, struct prim *pr, uint32_t ni, size_t first, size_t n, int depth)
{
	struct aabb box = aabb_empty(), cbox = aabb_empty();
	for (size_t i = first; i < first + n; i++) {
		grow(&box, &pr[i].box);
		grow_point(&cbox, pr[i].c);
	}
	b->nodes[ni].box = box;
	if (n <= LEAF_MAX || depth >= STACK_MAX - 2) {
		b->nodes[ni].first = (uint32_t)first;
		b->nodes[ni].count = (uint32_t)n;
		return;
	}
	/* Pick the axis and bin boundary with the least SAH cost. */
	double best = INFINITY;
	int best_axis = -1, best_split = 0;
	for (int a = 0; a < 3; a++) {
		double lo = v3_get(cbox.lo, a), ext = v3_get(cbox.hi, a) - lo;
		if (ext <= 0)
			continue;
		double scale = BINS / ext;
		struct aabb bb[BINS];
		size_t cnt[BINS] = {0};
		for (int k = 0; k < BINS; k++) bb[k] = aabb_empty();
		for (size_t i = first; i < first + n; i++) {
			int k = bin_of(v3_get(pr[i].c, a), lo, scale);
			cnt[k]++;
			grow(&bb[k], &pr[i].box);
		}
		double rarea[BINS];
		size_t rcnt[BINS];
		struct aabb acc = aabb_empty();
		size_t c = 0;
		for (int k = BINS - 1; k > 0; k--) {
			grow(&acc, &bb[k]);
			c += cnt[k];
			rarea[k] = aabb_area(acc);
			rcnt[k] = c;
		}
		acc = aabb_empty();
		c = 0;
		for (int k = 0; k < BINS - 1; k++) {
			grow(&acc, &bb[k]);
			c += cnt[k];
			if (c == 0 || rcnt[k + 1] == 0)
				continue;
			double cost = aabb_area(acc) * (double)c + rarea[k + 1] * (double)rcnt[k + 1];
			if (cost < best) {
				best = cost;
				best_axis = a;
				best_split = k + 1;
			}
		}
	}
	size_t mid;
	if (best_axis < 0) {
		mid = first + n / 2; /* all centroids coincide: split the list */
	} else {
		double lo = v3_get(cbox.lo, best_axis), scale = BINS / (v3_get(cbox.hi, best_axis) - lo);
		size_t i = first, j = first + n;
		while (i < j) {
			if (bin_of(v3_get(pr[i].c, best_axis), lo, scale) < best_split) {
				i++;
			} else {
				struct prim t = pr[i];
				pr[i] = pr[--j];
				pr[j] = t;
			}
		}
		mid = i;
		if (mid == first || mid == first + n)
			mid = first + n / 2;
	}
	uint32_t l = new_node(b);
	uint32_t r = new_node(b); /* children are allocated as a pair: r = l + 1 */
	b->nodes[ni].first = l;
	b->nodes[ni].count = 0;
	b->nodes[ni].axis = (uint32_t)(best_axis < 0 ? 0 : best_axis);
	build(b, pr, l, first, mid - first, depth + 1);
	build(b, pr, r, mid, first + n - mid, depth + 1);
}

struct bvh *bvh_build(struct object *const *objs, size_t n)
{
	struct bvh *b = calloc(1, sizeof *b);
	struct prim *pr = malloc((n ? n : 1) * sizeof *pr);
	if (!b || !pr) abort();
	b->nobjs = n;
	b->objs = malloc((n ? n : 1) * sizeof *b->objs);
	if (!b->objs) abort();
	/* A binary tree with leaves of at least one object has < 2n nodes. */
	b->cap = 2 * n + 1;
	b->nodes = malloc(b->cap * sizeof *b->nodes);
	if (!b->nodes) abort();
	for (size_t i = 0; i < n; i++) {
		pr[i].box = objs[i]->bounds;
		pr[i].c = aabb_center(objs[i]->bounds);
		pr[i].idx = (uint32_t)i;
	}
	uint32_t root = new_node(b);
	if (n > 0)
		build(b, pr, root, 0, n, 0);
	else
		b->nodes[root].box = aabb_empty();
	for (size_t i = 0; i < n; i++)
		b->objs[i] = objs[pr[i].idx];
	free(pr);
	return b;
}

void bvh_free(struct bvh *b)
{
	if (!b) return;
	free(b->nodes);
	free(b->objs);
	free(b);
}

size_t bvh_node_count(const struct bvh *b) { return b->nnodes; }

/* Slab test against a node box, with the ray's reciprocal direction. */
static inline bool box_entry(const struct aabb *bx, vec3 org, vec3 inv, double tmin, double tmax, double *entry)
{
	double t0 = (bx->lo.x - org.x) * inv.x, t1 = (bx->hi.x - org.x) * inv.x;
	if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
	tmin = t0 > tmin ? t0 : tmin;
	tmax = t1 < tmax ? t1 : tmax;
	t0 = (bx->lo.y - org.y) * inv.y; t1 = (bx->hi.y - org.y) * inv.y;
	if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
	tmin = t0 > tmin ? t0 : tmin;
	tmax = t1 < tmax ? t1 : tmax;
	t0 = (bx->lo.z - org.z) * inv.z; t1 = (bx->hi.z - org.z) * inv.z;
	if (t0 > t1) { double t = t0; t0 = t1; t1 = t; }
	tmin = t0 > tmin ? t0 : tmin;
	tmax = t1 < tmax ? t1 : tmax;
	/* NaN (0 * inf on a face plane) compares false and keeps the box. */
	*entry = tmin;
	return tmin <= tmax;
}

static inline bool box_hit(const struct aabb *bx, vec3 org, vec3 inv, double tmin, double tmax)
{
	double entry;
	return box_entry(bx, org, inv, tmin, tmax, &entry);
}

static vec3 reciprocal(vec3 d)
{
	return v3(1.0 / d.x, 1.0 / d.y, 1.0 / d.z);
}

bool bvh_intersect(const struct bvh *b, const struct ray *r, double tmin, double tmax, unsigned skip, struct hit *h,
                   const struct object **top)
{
	if (b->nobjs == 0)
		return false;
	vec3 inv = reciprocal(r->dir);
	/* Nearer child first; both children's boxes are tested at the parent
	 * and kept with their entry distance, so a subtree that starts past
	 * the closest hit found meanwhile is dropped unvisited. */
	struct {
		uint32_t node;
		double t;
	} stack[STACK_MAX];
	int sp = 0;
	double t0;
	if (!box_entry(&b->nodes[0].box, r->org, inv, tmin, tmax, &t0))
		return false;
	stack[sp].node = 0;
	stack[sp++].t = t0;
	bool found = false;
	while (sp > 0) {
		sp--;
		if (stack[sp].t > tmax)
			continue;
		const struct bvh_node *nd = &b->nodes[stack[sp].node];
		if (nd->count) {
			for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
				const struct object *o = b->objs[i];
				if (o->flags & skip)
					continue;
				/* An object whose box the ray misses is skipped: where the
				 * leaf holds several, a slab test costs less than most
				 * surfaces. A loose object may have surface outside its box;
				 * POV-Ray skips it there too, so that surface is not seen
				 * (see csg.c's culled). */
				if ((o->loose || nd->count > 1) && !box_hit(&o->bounds, r->org, inv, tmin, tmax))
					continue;
				struct hit th;
				if (object_intersect(o, r, tmin, tmax, &th)) {
					*h = th;
					tmax = th.t;
					found = true;
					if (top)
						*top = o;
				}
			}
		} else {
			uint32_t a = nd->first, c = nd->first + 1;
			double ta, tc;
			bool ha = box_entry(&b->nodes[a].box, r->org, inv, tmin, tmax, &ta);
			bool hc = box_entry(&b->nodes[c].box, r->org, inv, tmin, tmax, &tc);
			if (ha && hc) {
				bool a_first = ta <= tc;
				stack[sp].node = a_first ? c : a;
				stack[sp++].t = a_first ? tc : ta;
				stack[sp].node = a_first ? a : c;
				stack[sp++].t = a_first ? ta : tc;
			} else if (ha || hc) {
				stack[sp].node = ha ? a : c;
				stack[sp++].t = ha ? ta : tc;
			}
		}
	}
	return found;
}

bool bvh_occluded(const struct bvh *b, const struct ray *r, double tmin, double tmax, unsigned skip, const struct object **blocker)
{
	if (b->nobjs == 0)
		return false;
	vec3 inv = reciprocal(r->dir);
	uint32_t stack[STACK_MAX];
	int sp = 0;
	stack[sp++] = 0;
	struct hit h;
	while (sp > 0) {
		const struct bvh_node *nd = &b->nodes[stack[--sp]];
		if (!box_hit(&nd->box, r->org, inv, tmin, tmax))
			continue;
		if (nd->count) {
			for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
				const struct object *o = b->objs[i];
				if (o->flags & skip)
					continue;
				if ((o->loose || nd->count > 1) && !box_hit(&o->bounds, r->org, inv, tmin, tmax))
					continue;
				if (object_intersect(o, r, tmin, tmax, &h)) {
					*blocker = o;
					return true;
				}
			}
		} else {
			stack[sp++] = nd->first + 1;
			stack[sp++] = nd->first;
		}
	}
	return false;
}

bool bvh_inside_any(const struct bvh *b, vec3 p, const struct object *exclude)
{
	if (b->nobjs == 0)
		return false;
	uint32_t stack[STACK_MAX];
	int sp = 0;
	stack[sp++] = 0;
	while (sp > 0) {
		const struct bvh_node *nd = &b->nodes[stack[--sp]];
		const struct aabb *bx = &nd->box;
		if (p.x < bx->lo.x || p.x > bx->hi.x || p.y < bx->lo.y || p.y > bx->hi.y || p.z < bx->lo.z ||
		    p.z > bx->hi.z)
			continue;
		if (nd->count) {
			for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
				const struct object *o = b->objs[i];
				if (o != exclude && object_inside(o, p))
					return true;
			}
		} else {
			stack[sp++] = nd->first + 1;
			stack[sp++] = nd->first;
		}
	}
	return false;
}

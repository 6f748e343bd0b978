/* csg.c: union, merge, intersection and difference.
 *
 * A CSG object has no transform of its own: transforms go to its children
 * (object_transform walks `children`), so every child lives in the CSG's
 * world space and a hit returns the leaf primitive it found. Children go
 * into their own BVH (built by `prepare`), with unbounded children kept
 * aside; before prepare the children are scanned one by one, which is what
 * the parser's trace() and inside() see.
 *
 * The closest hit of merge, intersection and difference walks the
 * crossings of one group of children in increasing t and keeps the first
 * that lies on the result's boundary, judged by inside tests of the other
 * children, as POV-Ray does.
 *
 * Inverting a CSG follows De Morgan, as in POV-Ray: an inverted union is
 * the intersection of its inverted children, which keeps only the union's
 * outer surface; inverted again it becomes a merge of the children, never a
 * union. So a union under any inversion (its own `inverse`, an ancestor's,
 * or the place of a subtracted child of a difference, at any depth) walks
 * its crossings as a merge does (`as_merge`, set by csg_settle). Inverted
 * intersections, merges and differences keep the crossings they had. */
#include "geom/csg.h"

#include "accel/bvh.h"

#include <stdlib.h>

/* A guard against endless walks on degenerate input (crossings per ray and
 * group), far above what real scenes produce. */
enum { WALK_MAX = 100000 };

/* Children searched together: all of them (union, merge) or all but the
 * first (the subtracted ones of a difference). */
struct group {
	struct object **kids;    /* not owned: a range of the csg's array */
	size_t n;
	struct bvh *bvh;         /* the finite ones, after prepare; else NULL */
	struct object **unb;     /* the infinite ones, after prepare */
	size_t nunb;
};

struct csg {
	struct object base;
	enum csg_kind kind;
	bool split;              /* union: may be split into the scene's BVH */
	bool as_merge;           /* union under an inversion: no inner surfaces */
	bool settled;            /* everything below was inverted: as_merge set */
	struct aabb box;         /* world bounds kept since the first transform */
	bool boxed;              /* box is set (else computed from the children) */
	struct object **kids;    /* owned */
	size_t n, cap;
	struct group g;          /* union/merge: all; difference: kids[1..] */
};

static void group_clear(struct group *g)
{
	bvh_free(g->bvh);
	free(g->unb);
	g->bvh = NULL;
	g->unb = NULL;
	g->nunb = 0;
}

static void group_build(struct group *g)
{
	group_clear(g);
	struct object **fin = malloc((g->n ? g->n : 1) * sizeof *fin);
	g->unb = malloc((g->n ? g->n : 1) * sizeof *g->unb);
	if (!fin || !g->unb) abort();
	size_t nf = 0;
	for (size_t i = 0; i < g->n; i++) {
		/* A loose child's inside reaches beyond its box: the hierarchy's
		 * inside test would miss it. */
		if (aabb_is_finite(g->kids[i]->bounds) && !g->kids[i]->loose)
			fin[nf++] = g->kids[i];
		else
			g->unb[g->nunb++] = g->kids[i];
	}
	g->bvh = bvh_build(fin, nf);
	free(fin);
}

/* Does POV-Ray skip child k for a ray that misses k's box? It does for
 * the parts of a union, merge or intersection and the first part of a
 * difference, not for inverse or subtracted ones (measured with trace()
 * on an intersection { box { -2, 2 } union { sphere { 0, 1 inverse }
 * sphere { 3*x, 1 } } }, whose box, <-1,-1,-1> to <2,1,1>, cuts off
 * some of its surface: as a part of a union that surface is not found,
 * as a subtracted part it is). Only loose children can have surface
 * outside their box, so only they are tested here; the others are culled
 * by the group's hierarchy or not at all. */
static bool culled(const struct object *k, const struct ray *r, double tmin, double tmax)
{
	return k->loose && !(k->flags & OBJ_INVERSE) && !object_ray_meets_box(k->bounds, r, tmin, tmax);
}

/* Closest hit among the group's children in (tmin, tmax); *top is the
 * child that holds it. `cull`: skip loose children whose box the ray
 * misses (see culled). */
static bool group_closest(const struct group *g, const struct ray *r, double tmin, double tmax, struct hit *h,
                          const struct object **top, bool cull)
{
	bool found = false;
	struct object *const *list = g->kids;
	size_t n = g->n;
	if (g->bvh) {
		found = bvh_intersect(g->bvh, r, tmin, tmax, 0, h, top);
		if (found)
			tmax = h->t;
		list = g->unb;
		n = g->nunb;
	}
	for (size_t i = 0; i < n; i++) {
		struct hit th;
		if (cull && culled(list[i], r, tmin, tmax))
			continue;
		if (object_intersect(list[i], r, tmin, tmax, &th)) {
			*h = th;
			tmax = th.t;
			*top = list[i];
			found = true;
		}
	}
	return found;
}

/* Is p inside a child of the group other than `exclude`? */
static bool group_inside(const struct group *g, vec3 p, const struct object *exclude)
{
	struct object *const *list = g->kids;
	size_t n = g->n;
	if (g->bvh) {
		if (bvh_inside_any(g->bvh, p, exclude))
			return true;
		list = g->unb;
		n = g->nunb;
	}
	for (size_t i = 0; i < n; i++)
		if (list[i] != exclude && object_inside(list[i], p))
			return true;
	return false;
}

/* Is p inside every child but `exclude`? (intersection) */
static bool inside_all(const struct csg *c, vec3 p, const struct object *exclude)
{
	for (size_t i = 0; i < c->n; i++)
		if (c->kids[i] != exclude && !object_inside(c->kids[i], p))
			return false;
	return true;
}

/* Walk the crossings of one child in (tmin, tmax) and return the first
 * that `keep` accepts. */
static bool walk_child(const struct csg *c, const struct object *k, const struct ray *r, double tmin, double tmax,
                       struct hit *h, bool (*keep)(const struct csg *, const struct object *, vec3))
{
	if (culled(k, r, tmin, tmax))
		return false;
	for (int i = 0; i < WALK_MAX; i++) {
		if (!object_intersect(k, r, tmin, tmax, h))
			return false;
		if (keep(c, k, v3_madd(r->org, r->dir, h->t)))
			return true;
		tmin = h->t;
	}
	return false;
}

/* The same over the group's children together. */
static bool walk_group(const struct csg *c, const struct ray *r, double tmin, double tmax, struct hit *h,
                       bool (*keep)(const struct csg *, const struct object *, vec3))
{
	for (int i = 0; i < WALK_MAX; i++) {
		const struct object *top = NULL;
		if (!group_closest(&c->g, r, tmin, tmax, h, &top, c->kind != CSG_DIFFERENCE))
			return false;
		if (keep(c, top, v3_madd(r->org, r->dir, h->t)))
			return true;
		tmin = h->t;
	}
	return false;
}

/* merge: a child's surface counts where no other child covers it. */
static bool keep_merge(const struct csg *c, const struct object *k, vec3 p)
{
	return !group_inside(&c->g, p, k);
}

/* intersection: where every other child covers it. */
static bool keep_intersection(const struct csg *c, const struct object *k, vec3 p)
{
	return inside_all(c, p, k);
}

/* difference, first child's surface: where no subtracted child covers it. */
static bool keep_diff_first(const struct csg *c, const struct object *k, vec3 p)
{
	(void)k;
	return !group_inside(&c->g, p, NULL);
}

/* difference, a subtracted child's surface: inside the first child and
 * outside the other subtracted ones. */
static bool keep_diff_other(const struct csg *c, const struct object *k, vec3 p)
{
	return object_inside(c->kids[0], p) && !group_inside(&c->g, p, k);
}

static bool csg_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct csg *c = (const struct csg *)o;
	const struct object *top;
	switch (c->as_merge ? CSG_MERGE : c->kind) {
	case CSG_UNION:
		return group_closest(&c->g, r, tmin, tmax, h, &top, true);
	case CSG_MERGE:
		return walk_group(c, r, tmin, tmax, h, keep_merge);
	case CSG_INTERSECTION: {
		bool found = false;
		for (size_t i = 0; i < c->n; i++) {
			struct hit th;
			if (walk_child(c, c->kids[i], r, tmin, tmax, &th, keep_intersection)) {
				*h = th;
				tmax = th.t;
				found = true;
			}
		}
		return found;
	}
	case CSG_DIFFERENCE: {
		if (c->n == 0)
			return false;
		bool found = walk_child(c, c->kids[0], r, tmin, tmax, h, keep_diff_first);
		struct hit th;
		if (walk_group(c, r, tmin, found ? h->t : tmax, &th, keep_diff_other)) {
			*h = th;
			h->inverted = !h->inverted; /* a subtracted child's surface faces inward */
			found = true;
		}
		return found;
	}
	}
	return false;
}

/* Every crossing in (tmin, tmax), found by walking closest hits. */
static int csg_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	int n = 0;
	while (n < max && csg_intersect(o, r, tmin, tmax, &out[n])) {
		tmin = out[n].t;
		n++;
	}
	return n;
}

static bool csg_inside(const struct object *o, vec3 p)
{
	const struct csg *c = (const struct csg *)o;
	switch (c->kind) {
	case CSG_UNION:
	case CSG_MERGE:
		return group_inside(&c->g, p, NULL);
	case CSG_INTERSECTION:
		return c->n > 0 && inside_all(c, p, NULL);
	case CSG_DIFFERENCE:
		return c->n > 0 && object_inside(c->kids[0], p) && !group_inside(&c->g, p, NULL);
	}
	return false;
}

static vec3 csg_normal(const struct object *o, vec3 p, const struct hit *h)
{
	/* Never called: hits name the leaf primitive. */
	(void)o;
	(void)p;
	(void)h;
	return v3(0, 1, 0);
}

/* The bounds the children give now. */
static struct aabb children_bounds(const struct csg *c)
{
	struct aabb b = aabb_empty();
	switch (c->kind) {
	case CSG_UNION:
	case CSG_MERGE:
		for (size_t i = 0; i < c->n; i++)
			b = aabb_union(b, object_world_bounds(c->kids[i]));
		return b;
	case CSG_INTERSECTION:
	case CSG_DIFFERENCE: {
		/* The children's boxes cut one another; a difference is the
		 * intersection of the first child with the others inverted (an
		 * inverse plane is the other half-space; other inverse solids
		 * are unbounded). Measured in POV-Ray: six axis-aligned planes
		 * give their cube, and a box unbounded on any axis, or empty,
		 * is infinite -- also as the child of another intersection. */
		b = (struct aabb){{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
		for (size_t i = 0; i < c->n; i++) {
			struct aabb k = object_world_bounds_raw(c->kids[i], c->kind == CSG_DIFFERENCE && i > 0);
			b.lo = v3_max(b.lo, k.lo);
			b.hi = v3_min(b.hi, k.hi);
		}
		if (c->n == 0 || !aabb_is_finite(b) || b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z)
			b = (struct aabb){{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}};
		return b;
	}
	}
	return b;
}

static struct aabb csg_bounds(const struct object *o)
{
	const struct csg *c = (const struct csg *)o;
	return c->boxed ? c->box : children_bounds(c);
}

/* Before the first transform the box comes from the children; from then on
 * that box is moved with the object, as POV-Ray does (measured: six axis
 * planes rotated 45 degrees about y give x, z in +-1.414214; rotated back,
 * +-2; a union's box is its own box moved, not its moved children's). An
 * infinite box stays infinite. */
static void csg_transform_bounds(struct object *o, const struct xform *t)
{
	struct csg *c = (struct csg *)o;
	if (!c->boxed) {
		c->box = children_bounds(c);
		c->boxed = true;
	}
	if (aabb_is_finite(c->box))
		c->box = mat_bounds(&t->fwd, c->box);
}

static size_t csg_children(struct object *o, struct object ***kids)
{
	struct csg *c = (struct csg *)o;
	*kids = c->kids;
	return c->n;
}

static void set_group(struct csg *c)
{
	size_t first = c->kind == CSG_DIFFERENCE ? 1 : 0;
	c->g.kids = c->kids + (c->n ? first : 0);
	c->g.n = c->n > first ? c->n - first : 0;
}

/* Is the inside of a CSG of kind k with child i loose? The box of a union
 * covers its parts' boxes; an intersection's and a difference's cover only
 * the parts that are not inverted (inverse ones are left out, or give
 * their exact half-space), so only those parts count there. */
static bool child_loosens(enum csg_kind k, size_t i, const struct object *kid)
{
	if (k == CSG_UNION || k == CSG_MERGE)
		return kid->loose;
	bool inverted = ((kid->flags & OBJ_INVERSE) != 0) != (k == CSG_DIFFERENCE && i > 0);
	return kid->loose && !inverted;
}

static void csg_prepare(struct object *o)
{
	struct csg *c = (struct csg *)o;
	for (size_t i = 0; i < c->n; i++)
		o->loose = o->loose || child_loosens(c->kind, i, c->kids[i]);
	set_group(c);
	if (c->kind != CSG_INTERSECTION)
		group_build(&c->g);
}

static struct object *csg_copy(const struct object *o)
{
	const struct csg *c = (const struct csg *)o;
	struct csg *d = malloc(sizeof *d);
	if (!d) abort();
	*d = *c;
	d->kids = malloc((c->n ? c->n : 1) * sizeof *d->kids);
	if (!d->kids) abort();
	d->cap = c->n;
	for (size_t i = 0; i < c->n; i++)
		d->kids[i] = object_copy(c->kids[i]);
	d->g.bvh = NULL;
	d->g.unb = NULL;
	d->g.nunb = 0;
	set_group(d);
	return &d->base;
}

static void csg_destroy(struct object *o)
{
	struct csg *c = (struct csg *)o;
	group_clear(&c->g);
	for (size_t i = 0; i < c->n; i++)
		object_free(c->kids[i]);
	free(c->kids);
}

static const struct object_ops csg_ops = {
	.name = "csg",
	.intersect = csg_intersect,
	.all_hits = csg_all_hits,
	.inside = csg_inside,
	.normal = csg_normal,
	.bounds = csg_bounds,
	.children = csg_children,
	.transform_bounds = csg_transform_bounds,
	.prepare = csg_prepare,
	.copy = csg_copy,
	.destroy = csg_destroy,
};

/* o lies under an inversion: every union in it, o included, keeps only
 * its outer surface. */
static void mark_inverted(struct object *o)
{
	if (o->ops != &csg_ops)
		return;
	struct csg *c = (struct csg *)o;
	if (c->settled)
		return; /* its subtree was marked before */
	c->settled = true;
	if (c->kind == CSG_UNION)
		c->as_merge = true;
	for (size_t i = 0; i < c->n; i++)
		mark_inverted(c->kids[i]);
}

struct object *csg_new(enum csg_kind kind, struct srcpos pos)
{
	struct csg *c = calloc(1, sizeof *c);
	if (!c) abort();
	object_init(&c->base, &csg_ops, pos);
	c->kind = kind;
	c->split = true;
	return &c->base;
}

void csg_add(struct object *o, struct object *child)
{
	struct csg *c = (struct csg *)o;
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 4;
		c->kids = realloc(c->kids, c->cap * sizeof *c->kids);
		if (!c->kids) abort();
	}
	c->kids[c->n++] = child;
	c->boxed = false; /* a part after a transform (lucent only): from the parts */
	if ((c->kind == CSG_DIFFERENCE && c->n > 1) || (child->flags & OBJ_INVERSE))
		mark_inverted(child);
	/* The hierarchy, if any, no longer covers every child. */
	group_clear(&c->g);
	set_group(c);
}

bool csg_kind_of(const struct object *o, enum csg_kind *kind)
{
	if (o->ops != &csg_ops)
		return false;
	if (kind)
		*kind = ((const struct csg *)o)->kind;
	return true;
}

void csg_settle(struct object *o)
{
	if (o->ops != &csg_ops)
		return;
	struct csg *c = (struct csg *)o;
	if (o->flags & OBJ_INVERSE) {
		mark_inverted(o);
		return;
	}
	for (size_t i = 0; i < c->n; i++)
		if ((c->kind == CSG_DIFFERENCE && i > 0) || (c->kids[i]->flags & OBJ_INVERSE))
			mark_inverted(c->kids[i]);
}

void csg_set_split(struct object *o, bool split)
{
	((struct csg *)o)->split = split;
}

bool csg_splittable(const struct object *o)
{
	if (o->ops != &csg_ops)
		return false;
	const struct csg *c = (const struct csg *)o;
	return c->kind == CSG_UNION && !c->as_merge && c->split && !o->clip && !o->bound && !(o->flags & OBJ_INVERSE);
}

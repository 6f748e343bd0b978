/* blob.c: blob { components threshold T [sturm] [hierarchy] }, the surface
 * where the sum of the components' fields equals T (blob.h).
 *
 * Each component becomes elements with a simple field along a ray: a
 * sphere one (its field a quartic in t inside the sphere of its radius), a
 * cylinder three (the field of the distance to the axis between the end
 * planes, and a hemisphere beyond each end). A component with a transform
 * of its own keeps it, and its elements work in its space; the ray's t is
 * the same there. Along a ray every element is active on one interval;
 * between consecutive ends of those intervals the field is one quartic
 * (the sum of the active elements'), whose roots at the threshold are the
 * crossings. The quartics are written about the ray's entry into the
 * blob's box, so that their coefficients keep their precision far from
 * the origin.
 *
 * What POV-Ray does and lucent follows (measured with min_extent,
 * max_extent and trace()):
 *  - bounds: every element of positive strength has a bounding sphere,
 *    and the box is the union of their boxes (centre +- radius on every
 *    axis). A transformed element's radius is multiplied by the largest
 *    row sum of |M| (M: the component's transform times, for a cylinder,
 *    the rotation that takes z to the cylinder's axis the shortest way);
 *  - a sphere without a transform of its own takes a translate, rotate
 *    or uniform scale into its centre and radius (blob_transform_component);
 *  - crossings nearer than 0.01 to the ray's origin, measured along the
 *    world ray, are not reported (POV-Ray's depth tolerance for blobs: a
 *    point 0.0099 before the surface sees no hit, 0.0101 before sees it).
 */
#include "geom/blob.h"
#include "geom/solve.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The world distance below which a crossing is not reported. */
#define BLOB_MIN_DEPTH 0.01

enum elem_kind { EL_SPHERE, EL_CYLINDER, EL_BASE_CAP, EL_APEX_CAP };

struct comp {
	bool cyl;
	vec3 a, b;            /* the centre, or the cylinder's ends */
	double r, s;          /* radius (as given, may be negative) and strength */
	bool has_xf;
	struct xform xf;      /* blob_from_component */
	int first;            /* its first element */
};

struct elem {
	enum elem_kind kind;
	int comp;
	vec3 c;               /* sphere or cap centre; cylinder: the first end */
	vec3 u;               /* cylinder and caps: the unit axis from end 1 to end 2 */
	double len;           /* cylinder: the axis length */
	double r2;            /* radius squared */
	double s;             /* strength */
	vec3 bc;              /* bounding sphere in blob space */
	double br;
};

struct blob {
	struct object base;
	struct comp *comp;
	struct texture **tex; /* per component: one reference, or NULL (the blob's) */
	size_t ncomp, capc;
	struct elem *el;
	size_t nel, cape;
	double threshold;
	bool sturm, hierarchy;
	struct aabb box;      /* object-space bounds (positive elements) */
	bool box_stale;       /* a component moved since box was computed */
	bool any_tex;         /* some component has a texture (set by prepare) */
	struct bnode *node;   /* the hierarchy over the components (prepare), or NULL */
	int *order;           /* the components in the hierarchy's leaf order */
};

/* A node of the hierarchy: its box (the union of its components' element
 * spheres, negative ones included) and either two children or a run of
 * order[]. */
struct bnode {
	struct aabb box;
	int left, right;      /* children, or -1 for a leaf */
	int first, count;     /* a leaf's components: order[first .. first + count) */
};

enum { LEAF_SIZE = 4, TREE_DEPTH = 64 };

static struct blob *blob_of(const struct object *o)
{
	return (struct blob *)o;
}

/* The largest row sum of |m|'s linear part. */
static double row_sum(const double m[3][3])
{
	double best = 0;
	for (int i = 0; i < 3; i++)
		best = fmax(best, fabs(m[i][0]) + fabs(m[i][1]) + fabs(m[i][2]));
	return best;
}

/* The rotation taking z to the unit vector d the shortest way
 * (Rodrigues); d = -z turns half a turn about x. */
static void z_to(vec3 d, double R[3][3])
{
	vec3 v = v3(-d.y, d.x, 0); /* z x d */
	double s2 = v.x * v.x + v.y * v.y, c = d.z;
	double K[3][3] = {{0, -v.z, v.y}, {v.z, 0, -v.x}, {-v.y, v.x, 0}};
	if (s2 == 0) {
		double sg = c < 0 ? -1 : 1;
		double I[3][3] = {{1, 0, 0}, {0, sg, 0}, {0, 0, sg}};
		memcpy(R, I, sizeof I);
		return;
	}
	double f = (1 - c) / s2;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++) {
			double kk = 0;
			for (int k = 0; k < 3; k++)
				kk += K[i][k] * K[k][j];
			R[i][j] = (i == j) + K[i][j] + kk * f;
		}
}

/* Rebuild the elements of component ci (their geometry and bounds). */
static void refresh(struct blob *B, size_t ci)
{
	const struct comp *c = &B->comp[ci];
	struct elem *e = &B->el[c->first];
	double lin[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	if (c->has_xf)
		for (int i = 0; i < 3; i++)
			for (int j = 0; j < 3; j++)
				lin[i][j] = c->xf.fwd.m[i][j];
	double r = fabs(c->r);
	if (!c->cyl) {
		e[0] = (struct elem){.kind = EL_SPHERE, .comp = (int)ci, .c = c->a, .r2 = r * r, .s = c->s};
		e[0].bc = c->has_xf ? mat_point(&c->xf.fwd, c->a) : c->a;
		e[0].br = r * (c->has_xf ? row_sum(lin) : 1);
		return;
	}
	vec3 d = v3_sub(c->b, c->a);
	double len = v3_len(d);
	vec3 u = v3_scale(d, 1 / len);
	double R[3][3], M[3][3];
	z_to(u, R);
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			M[i][j] = lin[i][0] * R[0][j] + lin[i][1] * R[1][j] + lin[i][2] * R[2][j];
	double k = row_sum(M);
	vec3 mid = v3_madd(c->a, d, 0.5);
	struct elem base = {.comp = (int)ci, .u = u, .len = len, .r2 = r * r, .s = c->s};
	e[0] = base;
	e[0].kind = EL_CYLINDER;
	e[0].c = c->a;
	e[0].bc = c->has_xf ? mat_point(&c->xf.fwd, mid) : mid;
	e[0].br = sqrt(0.25 * len * len + r * r) * k;
	e[1] = base;
	e[1].kind = EL_BASE_CAP;
	e[1].c = c->a;
	e[1].bc = c->has_xf ? mat_point(&c->xf.fwd, c->a) : c->a;
	e[1].br = r * k;
	e[2] = base;
	e[2].kind = EL_APEX_CAP;
	e[2].c = c->b;
	e[2].bc = c->has_xf ? mat_point(&c->xf.fwd, c->b) : c->b;
	e[2].br = r * k;
}

/* Grow the box by the elements [from, B->nel) of positive strength. */
static void grow_box(struct blob *B, size_t from)
{
	for (size_t i = from; i < B->nel; i++) {
		const struct elem *e = &B->el[i];
		if (!(e->s > 0))
			continue;
		vec3 rr = v3(e->br, e->br, e->br);
		B->box.lo = v3_min(B->box.lo, v3_sub(e->bc, rr));
		B->box.hi = v3_max(B->box.hi, v3_add(e->bc, rr));
	}
}

/* The box, recomputed if a component moved since (a moved component may
 * shrink it). Recomputing once at the first use keeps a blob of many
 * transformed components linear to build; prepare does it before a
 * render, so that threads only read it. */
static const struct aabb *box_of(const struct blob *B)
{
	if (B->box_stale) {
		struct blob *m = (struct blob *)B;
		m->box = aabb_empty();
		grow_box(m, 0);
		m->box_stale = false;
	}
	return &B->box;
}

/* The box of component i's element spheres. */
static struct aabb comp_box(const struct blob *B, int i)
{
	const struct comp *c = &B->comp[i];
	struct aabb b = aabb_empty();
	for (int k = 0; k < (c->cyl ? 3 : 1); k++) {
		const struct elem *e = &B->el[c->first + k];
		vec3 rr = v3(e->br, e->br, e->br);
		b.lo = v3_min(b.lo, v3_sub(e->bc, rr));
		b.hi = v3_max(b.hi, v3_add(e->bc, rr));
	}
	return b;
}

static double axis_of(vec3 v, int k)
{
	return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

/* Build the subtree of order[first .. first + count) into node n (split at
 * the median of the boxes' centres along their widest axis); returns the
 * next free node. */
static int build_node(struct blob *B, const struct aabb *cb, int n, int first, int count, int depth)
{
	struct bnode *nd = &B->node[n];
	nd->box = aabb_empty();
	struct aabb cen = aabb_empty();
	for (int k = first; k < first + count; k++) {
		const struct aabb *b = &cb[B->order[k]];
		nd->box.lo = v3_min(nd->box.lo, b->lo);
		nd->box.hi = v3_max(nd->box.hi, b->hi);
		vec3 c = v3_scale(v3_add(b->lo, b->hi), 0.5);
		cen.lo = v3_min(cen.lo, c);
		cen.hi = v3_max(cen.hi, c);
	}
	nd->first = first;
	nd->count = count;
	nd->left = nd->right = -1;
	if (count <= LEAF_SIZE || depth >= TREE_DEPTH - 2)
		return n + 1;
	vec3 ext = v3_sub(cen.hi, cen.lo);
	int axis = ext.x >= ext.y && ext.x >= ext.z ? 0 : ext.y >= ext.z ? 1 : 2;
	/* Quickselect the median (Hoare's partition): linear on average. */
	int lo = first, hi = first + count - 1, mid = first + count / 2;
	while (lo < hi) {
		const struct aabb *pb = &cb[B->order[(lo + hi) / 2]];
		double pivot = axis_of(pb->lo, axis) + axis_of(pb->hi, axis);
		int a = lo, z = hi;
		while (a <= z) {
			while (axis_of(cb[B->order[a]].lo, axis) + axis_of(cb[B->order[a]].hi, axis) < pivot)
				a++;
			while (axis_of(cb[B->order[z]].lo, axis) + axis_of(cb[B->order[z]].hi, axis) > pivot)
				z--;
			if (a <= z) {
				int t = B->order[a];
				B->order[a] = B->order[z];
				B->order[z] = t;
				a++;
				z--;
			}
		}
		if (mid <= z)
			hi = z;
		else if (mid >= a)
			lo = a;
		else
			break;
	}
	int next = n + 1;
	nd = &B->node[n];
	nd->left = next;
	next = build_node(B, cb, next, first, mid - first, depth + 1);
	B->node[n].right = next;
	return build_node(B, cb, next, mid, first + count - mid, depth + 1);
}

static void drop_tree(struct blob *B)
{
	free(B->node);
	free(B->order);
	B->node = NULL;
	B->order = NULL;
}

/* The box, and with hierarchy on the tree over the components (read-only
 * while rendering; before prepare the components are scanned in turn). */
static void blob_prepare(struct object *o)
{
	struct blob *B = blob_of(o);
	box_of(B);
	B->any_tex = false;
	for (size_t i = 0; i < B->ncomp; i++)
		B->any_tex |= B->tex[i] != NULL;
	drop_tree(B);
	if (!B->hierarchy || B->ncomp <= LEAF_SIZE)
		return;
	int n = (int)B->ncomp;
	struct aabb *cb = malloc((size_t)n * sizeof *cb);
	B->order = malloc((size_t)n * sizeof *B->order);
	B->node = malloc((size_t)(2 * n) * sizeof *B->node);
	if (!cb || !B->order || !B->node) abort();
	for (int i = 0; i < n; i++) {
		cb[i] = comp_box(B, i);
		B->order[i] = i;
	}
	build_node(B, cb, 0, 0, n, 0);
	free(cb);
}

/* Call fn for every component whose box the ray (o, d) may cross (all of
 * them without a tree). */
typedef void (*comp_fn)(void *ctx, int comp);

/* Does the line o + t d (inv = 1 / d) cross box b? (The whole line: the
 * spans are cut to the ray's interval later.) */
static bool ray_box(const struct aabb *b, vec3 o, vec3 inv)
{
	double t0 = -INFINITY, t1 = INFINITY;
	for (int k = 0; k < 3; k++) {
		double oo = axis_of(o, k), iv = axis_of(inv, k);
		double lo = axis_of(b->lo, k), hi = axis_of(b->hi, k);
		if (isinf(iv)) {
			if (oo < lo || oo > hi)
				return false;
			continue;
		}
		span_narrow((lo - oo) * iv, (hi - oo) * iv, &t0, &t1);
	}
	return t0 <= t1 + 1e-12 * (1 + fabs(t1));
}

static void each_on_ray(const struct blob *B, vec3 o, vec3 d, comp_fn fn, void *ctx)
{
	if (!B->node) {
		for (size_t i = 0; i < B->ncomp; i++)
			fn(ctx, (int)i);
		return;
	}
	vec3 inv = v3(1 / d.x, 1 / d.y, 1 / d.z);
	int stack[TREE_DEPTH], top = 0;
	stack[top++] = 0;
	while (top > 0) {
		const struct bnode *nd = &B->node[stack[--top]];
		if (!ray_box(&nd->box, o, inv))
			continue;
		if (nd->left < 0) {
			for (int k = nd->first; k < nd->first + nd->count; k++)
				fn(ctx, B->order[k]);
			continue;
		}
		stack[top++] = nd->right;
		stack[top++] = nd->left;
	}
}

static bool box_has(struct aabb b, vec3 p)
{
	return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y && p.z >= b.lo.z && p.z <= b.hi.z;
}

static void each_at_point(const struct blob *B, vec3 p, comp_fn fn, void *ctx)
{
	if (!B->node) {
		for (size_t i = 0; i < B->ncomp; i++)
			fn(ctx, (int)i);
		return;
	}
	int stack[TREE_DEPTH], top = 0;
	stack[top++] = 0;
	while (top > 0) {
		const struct bnode *nd = &B->node[stack[--top]];
		if (!box_has(nd->box, p))
			continue;
		if (nd->left < 0) {
			for (int k = nd->first; k < nd->first + nd->count; k++)
				fn(ctx, B->order[k]);
			continue;
		}
		stack[top++] = nd->right;
		stack[top++] = nd->left;
	}
}

/* ---- the field along a ray ---- */

/* q(t) = |p(t) - axis part|^2 / r^2 = qa t^2 + qb t + qc for element e
 * along the component-space ray (o, d), and the interval [lo, hi] where
 * the element is active (q < 1 and within its region); false if none. */
static bool elem_span(const struct elem *e, vec3 o, vec3 d, double q[3], double *lo, double *hi)
{
	if (!(e->r2 > 0))
		return false;
	vec3 w = v3_sub(o, e->c), dd = d;
	double g0 = 0, g1 = 0; /* the position along the axis: g0 + t g1 */
	if (e->kind != EL_SPHERE) {
		g0 = v3_dot(w, e->u);
		g1 = v3_dot(d, e->u);
	}
	if (e->kind == EL_CYLINDER) {
		w = v3_madd(w, e->u, -g0);
		dd = v3_madd(d, e->u, -g1);
	}
	double inv = 1 / e->r2;
	double a = v3_dot(dd, dd) * inv, b = 2 * v3_dot(w, dd) * inv, c = v3_dot(w, w) * inv;
	q[0] = c;
	q[1] = b;
	q[2] = a;
	double t0, t1;
	if (a > 0) {
		/* Stable roots of a t^2 + b t + c - 1. */
		double disc = b * b - 4 * a * (c - 1);
		if (disc <= 0)
			return false;
		double sq = sqrt(disc), qq = -0.5 * (b + copysign(sq, b));
		double ra = qq / a, rb = qq != 0 ? (c - 1) / qq : -ra;
		t0 = ra < rb ? ra : rb;
		t1 = ra < rb ? rb : ra;
	} else if (c < 1) {
		t0 = -INFINITY;
		t1 = INFINITY;
	} else {
		return false;
	}
	/* The element's region along its axis. */
	double alo = -INFINITY, ahi = INFINITY; /* allowed g */
	if (e->kind == EL_CYLINDER) {
		alo = 0;
		ahi = e->len;
	} else if (e->kind == EL_BASE_CAP) {
		ahi = 0;
	} else if (e->kind == EL_APEX_CAP) {
		alo = 0; /* e->c is the second end */
	}
	if (e->kind != EL_SPHERE) {
		if (g1 != 0)
			span_narrow((alo - g0) / g1, (ahi - g0) / g1, &t0, &t1);
		else if (g0 < alo || g0 > ahi)
			return false;
	}
	if (!(t0 < t1))
		return false;
	*lo = t0;
	*hi = t1;
	return true;
}

/* The element's field s (1 - q)^2 as a quartic in t, added times sign
 * into p[0..4]. */
static void add_quartic(const struct elem *e, const double q[3], double sign, double p[5])
{
	double E = 1 - q[0], b = q[1], a = q[2], s = e->s * sign;
	p[0] += s * E * E;
	p[1] += s * -2 * E * b;
	p[2] += s * (b * b - 2 * E * a);
	p[3] += s * 2 * a * b;
	p[4] += s * a * a;
}

struct span {
	double lo, hi;
	double q[3];
	int el;
};

struct event {
	double t;
	int span;
	int enter;
};

static int event_cmp(const void *pa, const void *pb)
{
	const struct event *a = pa, *b = pb;
	if (a->t != b->t)
		return a->t < b->t ? -1 : 1;
	return b->enter - a->enter; /* enter before leave at one t */
}

/* The ray against the bounding sphere of e (blob space). */
static bool hits_sphere(const struct elem *e, vec3 o, vec3 d, double dd)
{
	vec3 w = v3_sub(e->bc, o);
	double t = v3_dot(w, d) / dd;
	vec3 perp = v3_madd(w, d, -t);
	return v3_dot(perp, perp) <= e->br * e->br * (1 + 1e-9);
}

typedef bool (*root_sink)(void *ctx, double t);

enum { STACK_SPANS = 128 };

/* The spans of the elements along one ray (blob_hits). */
struct span_ctx {
	const struct blob *B;
	vec3 org, d, so;      /* the ray, and its origin shifted to the box entry */
	double dd;
	struct span *sp;      /* stack_spans, or a heap array when more are needed */
	struct event *ev;     /* room for two events a span */
	size_t n, cap;
	struct span stack_spans[STACK_SPANS];
	struct event stack_ev[2 * STACK_SPANS];
};

/* Add the spans of component ci's elements that the ray crosses. */
static void add_spans(void *ctx, int ci)
{
	struct span_ctx *sc = ctx;
	const struct blob *B = sc->B;
	const struct comp *c = &B->comp[ci];
	for (int k = 0; k < (c->cyl ? 3 : 1); k++) {
		const struct elem *e = &B->el[c->first + k];
		if (!hits_sphere(e, sc->org, sc->d, sc->dd))
			continue;
		vec3 lo_o = sc->so, lo_d = sc->d;
		if (c->has_xf) {
			lo_o = mat_point(&c->xf.inv, sc->so);
			lo_d = mat_dir(&c->xf.inv, sc->d);
		}
		struct span s;
		if (!elem_span(e, lo_o, lo_d, s.q, &s.lo, &s.hi))
			continue;
		if (sc->n == sc->cap) {
			/* Rare: more active elements along one ray than the stack
			 * holds. */
			size_t ncap = sc->cap * 2;
			struct span *nsp = malloc(ncap * sizeof *nsp);
			struct event *nev = malloc(2 * ncap * sizeof *nev);
			if (!nsp || !nev) abort();
			memcpy(nsp, sc->sp, sc->n * sizeof *nsp);
			if (sc->sp != sc->stack_spans) {
				free(sc->sp);
				free(sc->ev);
			}
			sc->sp = nsp;
			sc->ev = nev;
			sc->cap = ncap;
		}
		s.el = c->first + k;
		sc->sp[sc->n++] = s;
	}
}

/* Report the crossings in (tmin, tmax) in increasing t to take, which
 * returns whether to go on. */
static void blob_hits(const struct object *o, const struct ray *r, double tmin, double tmax, root_sink take,
                      void *ctx)
{
	const struct blob *B = blob_of(o);
	vec3 org = r->org, d = r->dir;
	double dd = v3_dot(d, d);
	if (!(dd > 0) || B->nel == 0)
		return;
	/* POV-Ray's depth tolerance, along the world ray. */
	double wlen = o->has_xf ? v3_len(mat_dir(&o->xf.fwd, d)) : sqrt(dd);
	tmin = fmax(tmin, BLOB_MIN_DEPTH / wlen);
	/* The entry into the box: the origin of the quartics. */
	const struct aabb *box = box_of(B);
	double t0 = -INFINITY, t1 = INFINITY;
	for (int k = 0; k < 3; k++) {
		double oo = k == 0 ? org.x : k == 1 ? org.y : org.z, dk = k == 0 ? d.x : k == 1 ? d.y : d.z;
		double lo = k == 0 ? box->lo.x : k == 1 ? box->lo.y : box->lo.z;
		double hi = k == 0 ? box->hi.x : k == 1 ? box->hi.y : box->hi.z;
		if (dk != 0) {
			double ta = (lo - oo) / dk, tb = (hi - oo) / dk;
			t0 = fmax(t0, fmin(ta, tb));
			t1 = fmin(t1, fmax(ta, tb));
		} else if (oo < lo || oo > hi) {
			return;
		}
	}
	if (!(t0 <= t1) || t1 < tmin || t0 > tmax)
		return;
	/* Set field by field: zeroing the stack arrays would cost more than
	 * the search (11 KB a ray). */
	struct span_ctx sc;
	sc.B = B;
	sc.org = org;
	sc.d = d;
	sc.dd = dd;
	sc.so = v3_madd(org, d, t0);
	sc.n = 0;
	sc.cap = STACK_SPANS;
	sc.sp = sc.stack_spans;
	sc.ev = sc.stack_ev;
	each_on_ray(B, org, d, add_spans, &sc);
	struct span *sp = sc.sp;
	struct event *ev = sc.ev;
	size_t n = sc.n;
	size_t ne = 0;
	for (size_t i = 0; i < n; i++) {
		ev[ne++] = (struct event){sp[i].lo, (int)i, 1};
		ev[ne++] = (struct event){sp[i].hi, (int)i, 0};
	}
	if (ne <= 64) {
		/* Few events (the usual case): insertion sort, no call per
		 * comparison. */
		for (size_t k = 1; k < ne; k++) {
			struct event x = ev[k];
			size_t m = k;
			while (m > 0 && event_cmp(&ev[m - 1], &x) > 0) {
				ev[m] = ev[m - 1];
				m--;
			}
			ev[m] = x;
		}
	} else {
		qsort(ev, ne, sizeof *ev, event_cmp);
	}
	double p[5] = {0, 0, 0, 0, 0};
	int active = 0;
	double taumin = tmin - t0, taumax = tmax - t0;
	for (size_t k = 0; k + 1 < ne; k++) {
		const struct span *s = &sp[ev[k].span];
		add_quartic(&B->el[s->el], s->q, ev[k].enter ? 1 : -1, p);
		active += ev[k].enter ? 1 : -1;
		if (active == 0) {
			memset(p, 0, sizeof p);
			continue;
		}
		double lo = ev[k].t, hi = ev[k + 1].t;
		if (!(hi > lo) || hi <= taumin || lo >= taumax)
			continue;
		double c[5] = {p[0] - B->threshold, p[1], p[2], p[3], p[4]};
		double w = 1e-9 * fmax(1, fmax(fabs(lo), fabs(hi)));
		double roots[4];
		int nr = solve_poly(c, 4, lo - w, hi + w, B->sturm, roots);
		for (int j = 0; j < nr; j++) {
			double tau = roots[j];
			/* A root on the boundary belongs to the first interval. */
			if (tau < lo && k > 0)
				continue;
			if (tau > hi)
				tau = hi;
			if (tau < lo)
				tau = lo;
			/* Compared in t: t0 + tau may round onto tmin when tau is
			 * just above tmin - t0 (a CSG asking again from a hit). */
			double t = t0 + tau;
			if (!(t > tmin && t < tmax))
				continue;
			if (!take(ctx, t))
				goto done;
		}
	}
done:
	if (sp != sc.stack_spans) {
		free(sp);
		free(ev);
	}
}

struct first_root {
	double t;
	bool found;
};

static bool take_first(void *ctx, double t)
{
	struct first_root *f = ctx;
	f->t = t;
	f->found = true;
	return false;
}

static bool blob_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct first_root f = {0, false};
	blob_hits(o, r, tmin, tmax, take_first, &f);
	if (!f.found)
		return false;
	h->t = f.t;
	h->part = 0;
	return true;
}

struct all_roots {
	const struct object *o;
	struct hit *out;
	int n, max;
	double last;
};

static bool take_all(void *ctx, double t)
{
	struct all_roots *a = ctx;
	if (a->n >= a->max)
		return false;
	if (a->n > 0 && t <= a->last)
		return true; /* a root on a joint found twice */
	a->out[a->n++] = (struct hit){.t = t, .obj = a->o, .part = 0};
	a->last = t;
	return true;
}

static int blob_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                         int max)
{
	struct all_roots a = {o, out, 0, max, 0};
	blob_hits(o, r, tmin, tmax, take_all, &a);
	return a.n;
}

/* ---- the field at a point ---- */

/* The field of element e at the component-space point p, and (if grad)
 * its gradient there (component space). */
static double elem_field(const struct elem *e, vec3 p, vec3 *grad)
{
	if (!(e->r2 > 0))
		return 0;
	vec3 w = v3_sub(p, e->c);
	if (e->kind != EL_SPHERE) {
		double g = v3_dot(w, e->u);
		if (e->kind == EL_CYLINDER) {
			if (g < 0 || g > e->len)
				return 0;
			w = v3_madd(w, e->u, -g);
		} else if (e->kind == EL_BASE_CAP ? g > 0 : g < 0) {
			return 0;
		}
	}
	double q = v3_dot(w, w) / e->r2;
	if (!(q < 1))
		return 0;
	if (grad)
		*grad = v3_scale(w, -4 * e->s * (1 - q) / e->r2);
	return e->s * (1 - q) * (1 - q);
}

/* The field of component c at the blob-space point p, adding its
 * gradient (blob space) to *grad if grad. */
static double comp_field(const struct blob *B, const struct comp *c, vec3 p, vec3 *grad)
{
	vec3 lp = c->has_xf ? mat_point(&c->xf.inv, p) : p;
	int n = c->cyl ? 3 : 1;
	double f = 0;
	vec3 g = v3(0, 0, 0);
	for (int k = 0; k < n; k++) {
		vec3 gk = v3(0, 0, 0);
		f += elem_field(&B->el[c->first + k], lp, grad ? &gk : NULL);
		g = v3_add(g, gk);
	}
	if (grad) {
		if (c->has_xf)
			g = mat_normal(&c->xf.inv, g);
		*grad = v3_add(*grad, g);
	}
	return f;
}

static bool near_comp(const struct blob *B, const struct comp *c, vec3 p)
{
	int n = c->cyl ? 3 : 1;
	for (int k = 0; k < n; k++) {
		const struct elem *e = &B->el[c->first + k];
		vec3 w = v3_sub(p, e->bc);
		if (v3_dot(w, w) <= e->br * e->br * (1 + 1e-9))
			return true;
	}
	return false;
}

/* Sums of the fields at one point (blob_density, the normal, the
 * texture blend). */
struct field_ctx {
	const struct blob *B;
	vec3 p;
	double f;
	vec3 grad;
	bool want_grad;
};

static void add_field(void *ctx, int ci)
{
	struct field_ctx *fc = ctx;
	const struct comp *c = &fc->B->comp[ci];
	if (near_comp(fc->B, c, fc->p))
		fc->f += comp_field(fc->B, c, fc->p, fc->want_grad ? &fc->grad : NULL);
}

double blob_density(const struct object *o, vec3 p)
{
	struct field_ctx fc = {.B = blob_of(o), .p = p};
	each_at_point(fc.B, p, add_field, &fc);
	return fc.f;
}

static bool blob_inside(const struct object *o, vec3 p)
{
	return blob_density(o, p) > blob_of(o)->threshold;
}

/* The outward normal: minus the field's gradient. */
static vec3 blob_normal(const struct object *o, vec3 p, const struct hit *h)
{
	(void)h;
	struct field_ctx fc = {.B = blob_of(o), .p = p, .want_grad = true};
	each_at_point(fc.B, p, add_field, &fc);
	vec3 n = v3_neg(fc.grad);
	if (n.x == 0 && n.y == 0 && n.z == 0)
		return v3(0, 1, 0);
	return n;
}

static struct aabb blob_bounds(const struct object *o)
{
	return *box_of(blob_of(o));
}

/* The component textures at p, weighted by the components' fields there
 * (those of positive field; one without a texture of its own shows the
 * blob's). */
struct blend_ctx {
	const struct object *o;
	vec3 p;
	const struct texture **tex;
	double *w, sum;
	int n, max;
};

static void add_blend(void *ctx, int ci)
{
	struct blend_ctx *bc = ctx;
	const struct blob *B = blob_of(bc->o);
	const struct comp *c = &B->comp[ci];
	if (!near_comp(B, c, bc->p))
		return;
	double f = comp_field(B, c, bc->p, NULL);
	if (!(f > 0))
		return;
	const struct texture *t = B->tex[ci] ? B->tex[ci] : bc->o->tex;
	int j = 0;
	while (j < bc->n && bc->tex[j] != t)
		j++;
	if (j == bc->n) {
		if (bc->n == bc->max)
			return;
		bc->tex[bc->n] = t;
		bc->w[bc->n++] = 0;
	}
	bc->w[j] += f;
	bc->sum += f;
}

static int blob_texture_blend(const struct object *o, vec3 p, const struct texture **tex, double *w, int max)
{
	const struct blob *B = blob_of(o);
	if (!B->any_tex)
		return 0;
	struct blend_ctx bc = {.o = o, .p = p, .tex = tex, .w = w, .max = max};
	each_at_point(B, p, add_blend, &bc);
	if (bc.n == 0 || !(bc.sum > 0))
		return 0;
	for (int j = 0; j < bc.n; j++)
		w[j] /= bc.sum;
	return bc.n;
}

static size_t blob_textures(const struct object *o, struct texture *const **tex)
{
	*tex = blob_of(o)->tex;
	return blob_of(o)->ncomp;
}

static void blob_transform_textures(struct object *o, const struct xform *t)
{
	struct blob *B = blob_of(o);
	for (size_t i = 0; i < B->ncomp; i++)
		if (B->tex[i])
			B->tex[i] = texture_transform(B->tex[i], t);
}

static struct object *blob_copy(const struct object *o)
{
	const struct blob *B = blob_of(o);
	struct blob *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *B;
	c->comp = malloc((B->capc ? B->capc : 1) * sizeof *c->comp);
	c->tex = malloc((B->capc ? B->capc : 1) * sizeof *c->tex);
	c->el = malloc((B->cape ? B->cape : 1) * sizeof *c->el);
	if (!c->comp || !c->tex || !c->el) abort();
	if (B->ncomp) {
		memcpy(c->comp, B->comp, B->ncomp * sizeof *c->comp);
		memcpy(c->tex, B->tex, B->ncomp * sizeof *c->tex);
		memcpy(c->el, B->el, B->nel * sizeof *c->el);
	}
	for (size_t i = 0; i < c->ncomp; i++)
		if (c->tex[i])
			texture_ref(c->tex[i]);
	c->node = NULL; /* rebuilt by the copy's prepare */
	c->order = NULL;
	return &c->base;
}

static void blob_destroy(struct object *o)
{
	struct blob *B = blob_of(o);
	for (size_t i = 0; i < B->ncomp; i++)
		texture_unref(B->tex[i]);
	free(B->comp);
	free(B->tex);
	drop_tree(B);
	free(B->el);
}

static const struct object_ops blob_ops = {
	.name = "blob",
	.intersect = blob_intersect,
	.all_hits = blob_all_hits,
	.inside = blob_inside,
	.normal = blob_normal,
	.bounds = blob_bounds,
	.textures = blob_textures,
	.texture_blend = blob_texture_blend,
	.transform_textures = blob_transform_textures,
	.prepare = blob_prepare,
	.copy = blob_copy,
	.destroy = blob_destroy,
};

/* ---- building ---- */

struct object *blob_new(struct srcpos pos)
{
	struct blob *B = calloc(1, sizeof *B);
	if (!B) abort();
	object_init(&B->base, &blob_ops, pos);
	B->threshold = 1;
	B->hierarchy = true;
	B->box = aabb_empty();
	return &B->base;
}

static int add_comp(struct blob *B, struct comp c)
{
	int nel = c.cyl ? 3 : 1;
	if (B->ncomp == B->capc) {
		B->capc = B->capc ? 2 * B->capc : 8;
		B->comp = realloc(B->comp, B->capc * sizeof *B->comp);
		B->tex = realloc(B->tex, B->capc * sizeof *B->tex);
		if (!B->comp || !B->tex) abort();
	}
	if (B->nel + (size_t)nel > B->cape) {
		B->cape = B->cape ? 2 * B->cape + 3 : 16;
		B->el = realloc(B->el, B->cape * sizeof *B->el);
		if (!B->el) abort();
	}
	c.first = (int)B->nel;
	B->nel += (size_t)nel;
	B->comp[B->ncomp] = c;
	B->tex[B->ncomp] = NULL;
	refresh(B, B->ncomp);
	grow_box(B, (size_t)c.first);
	drop_tree(B);
	return (int)B->ncomp++;
}

int blob_add_sphere(struct object *o, vec3 center, double radius, double strength)
{
	struct comp c = {.cyl = false, .a = center, .r = radius, .s = strength, .xf = xform_identity()};
	return add_comp(blob_of(o), c);
}

int blob_add_cylinder(struct object *o, vec3 end1, vec3 end2, double radius, double strength)
{
	if (!(v3_len(v3_sub(end2, end1)) > 0))
		return -1;
	struct comp c = {.cyl = true, .a = end1, .b = end2, .r = radius, .s = strength, .xf = xform_identity()};
	return add_comp(blob_of(o), c);
}

void blob_transform_component(struct object *o, int i, const struct xform *t, bool rigid)
{
	struct blob *B = blob_of(o);
	struct comp *c = &B->comp[i];
	if (rigid && !c->cyl && !c->has_xf) {
		vec3 col = v3(t->fwd.m[0][0], t->fwd.m[1][0], t->fwd.m[2][0]);
		c->a = mat_point(&t->fwd, c->a);
		c->r *= v3_len(col);
	} else {
		c->xf = xform_compose(t, &c->xf);
		c->has_xf = true;
	}
	if (B->tex[i])
		B->tex[i] = texture_transform(B->tex[i], t);
	refresh(B, (size_t)i);
	B->box_stale = true;
	drop_tree(B);
}

struct texture **blob_component_texture(struct object *o, int i)
{
	return &blob_of(o)->tex[i];
}

size_t blob_component_count(const struct object *o)
{
	return blob_of(o)->ncomp;
}

void blob_set_threshold(struct object *o, double threshold)
{
	blob_of(o)->threshold = threshold;
}

void blob_set_sturm(struct object *o, bool sturm)
{
	blob_of(o)->sturm = sturm;
}

void blob_set_hierarchy(struct object *o, bool on)
{
	blob_of(o)->hierarchy = on;
}

/* mesh.c: triangle meshes (see mesh.h): the builder, the shared data with
 * its bounding volume hierarchy, and the object's operations. */
#include "geom/mesh.h"
#include "geom/tri.h"
#include "math/hash.h"

#include <float.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

enum {
	BINS = 16,       /* SAH bins per axis */
	LEAF_MIN = 2,    /* nodes this small are leaves: halves the node count of sparse meshes */
	LEAF_MAX = 4,    /* triangles per leaf at most */
	DEPTH_MAX = 64,  /* past this depth, nodes are split at the middle of their list */
	PAR_MIN = 1 << 16, /* subtrees this large are built on a thread of their own... */
	PAR_DEPTH = 2,     /* ...down to this depth (at most 4 subtrees at once) */
	STACK_MAX = 128, /* > DEPTH_MAX + 32 + 1: the deepest tree a 2^32 list can give */
};

struct idx3 {
	uint32_t i[3];
};

/* ---- the builder ---- */

/* A growable list of vectors, with an open-addressing table of indices for
 * merging equal entries (slot == NULL: no merging). */
struct vlist {
	vec3 *v;
	uint32_t n, cap;
	uint32_t *slot;  /* MESH_NONE: empty */
	uint32_t nslot;  /* a power of two, at least twice n */
};

struct mesh_builder {
	enum mesh_kind kind;
	struct vlist verts, normals, uvs;
	struct texture **tex; /* one reference each */
	uint32_t ntex, tex_cap;
	/* Per face. face_n, face_uv and face_tex stay NULL until a face needs
	 * them; they share face's capacity. */
	struct idx3 *face, *face_n, *face_uv, *face_tex;
	uint32_t nface, face_cap;
	vec3 inside;
};

/* p (capacity *cap elements of size elem) grown to hold `need`; returns
 * the new pointer. */
static void *grow(void *p, uint32_t *cap, uint32_t need, size_t elem)
{
	if (need <= *cap)
		return p;
	if (need >= MESH_NONE) abort(); /* indices are 32-bit with one value reserved */
	uint64_t c = *cap ? *cap : 16;
	while (c < need) c *= 2;
	if (c >= MESH_NONE) c = MESH_NONE - 1;
	void *q = realloc(p, (size_t)c * elem);
	if (!q) abort();
	*cap = (uint32_t)c;
	return q;
}

/* p resized to n elements (at least one); NULL stays NULL. */
static void *resize(void *p, size_t n, size_t elem)
{
	if (!p)
		return NULL;
	void *q = realloc(p, (n ? n : 1) * elem);
	if (!q) abort();
	return q;
}

static uint64_t bits(double x)
{
	uint64_t u;
	memcpy(&u, &x, sizeof u);
	return u;
}

static uint32_t vec_hash(vec3 p)
{
	return (uint32_t)hash_mix(bits(p.x) ^ hash_mix(bits(p.y) ^ hash_mix(bits(p.z))));
}

static void vlist_rehash(struct vlist *l, uint32_t nslot)
{
	free(l->slot);
	l->slot = malloc((size_t)nslot * sizeof *l->slot);
	if (!l->slot) abort();
	memset(l->slot, 0xff, (size_t)nslot * sizeof *l->slot); /* MESH_NONE */
	l->nslot = nslot;
	for (uint32_t i = 0; i < l->n; i++) {
		uint32_t h = vec_hash(l->v[i]) & (nslot - 1);
		while (l->slot[h] != MESH_NONE)
			h = (h + 1) & (nslot - 1);
		l->slot[h] = i;
	}
}

/* Append p, or with merging find an equal entry first. -0 is stored as +0
 * so that equal coordinates merge. */
static uint32_t vlist_add(struct vlist *l, vec3 p)
{
	p = v3(p.x + 0.0, p.y + 0.0, p.z + 0.0);
	uint32_t h = 0;
	if (l->slot) {
		if ((uint64_t)2 * (l->n + 1) > l->nslot)
			vlist_rehash(l, l->nslot * 2);
		uint32_t mask = l->nslot - 1;
		h = vec_hash(p) & mask;
		for (uint32_t i; (i = l->slot[h]) != MESH_NONE; h = (h + 1) & mask)
			if (l->v[i].x == p.x && l->v[i].y == p.y && l->v[i].z == p.z)
				return i;
	}
	l->v = grow(l->v, &l->cap, l->n + 1, sizeof *l->v);
	if (l->slot)
		l->slot[h] = l->n;
	l->v[l->n] = p;
	return l->n++;
}

static void vlist_free(struct vlist *l)
{
	free(l->v);
	free(l->slot);
}

struct mesh_builder *mesh_builder_new(enum mesh_kind kind)
{
	struct mesh_builder *b = calloc(1, sizeof *b);
	if (!b) abort();
	b->kind = kind;
	if (kind == MESH_KIND_MESH) {
		vlist_rehash(&b->verts, 64);
		vlist_rehash(&b->normals, 64);
		vlist_rehash(&b->uvs, 64);
	}
	return b;
}

void mesh_builder_free(struct mesh_builder *b)
{
	if (!b) return;
	vlist_free(&b->verts);
	vlist_free(&b->normals);
	vlist_free(&b->uvs);
	for (uint32_t i = 0; i < b->ntex; i++)
		texture_unref(b->tex[i]);
	free(b->tex);
	free(b->face);
	free(b->face_n);
	free(b->face_uv);
	free(b->face_tex);
	free(b);
}

uint32_t mesh_add_vertex(struct mesh_builder *b, vec3 p) { return vlist_add(&b->verts, p); }
uint32_t mesh_add_normal(struct mesh_builder *b, vec3 n) { return vlist_add(&b->normals, v3_norm(n)); }
uint32_t mesh_add_uv(struct mesh_builder *b, double u, double v) { return vlist_add(&b->uvs, v3(u, v, 0)); }

uint32_t mesh_add_texture(struct mesh_builder *b, struct texture *t)
{
	if (b->kind == MESH_KIND_MESH)
		for (uint32_t i = 0; i < b->ntex; i++)
			if (b->tex[i] == t)
				return i;
	b->tex = grow(b->tex, &b->tex_cap, b->ntex + 1, sizeof *b->tex);
	b->tex[b->ntex] = texture_ref(t);
	return b->ntex++;
}

uint32_t mesh_vertex_count(const struct mesh_builder *b) { return b->verts.n; }
uint32_t mesh_normal_count(const struct mesh_builder *b) { return b->normals.n; }
uint32_t mesh_uv_count(const struct mesh_builder *b) { return b->uvs.n; }
uint32_t mesh_texture_count(const struct mesh_builder *b) { return b->ntex; }
uint32_t mesh_face_count(const struct mesh_builder *b) { return b->nface; }

static const struct idx3 no_idx = {{MESH_NONE, MESH_NONE, MESH_NONE}};

/* Make room for `need` faces in every per-face array in use. */
static void face_reserve(struct mesh_builder *b, uint32_t need)
{
	if (need <= b->face_cap)
		return;
	uint32_t cap = b->face_cap;
	b->face = grow(b->face, &cap, need, sizeof *b->face);
	b->face_n = resize(b->face_n, cap, sizeof *b->face_n);
	b->face_uv = resize(b->face_uv, cap, sizeof *b->face_uv);
	b->face_tex = resize(b->face_tex, cap, sizeof *b->face_tex);
	b->face_cap = cap;
}

/* The optional per-face array *arr, created (all MESH_NONE) on first use. */
static struct idx3 *face_opt(struct mesh_builder *b, struct idx3 **arr)
{
	if (!*arr) {
		*arr = malloc((size_t)(b->face_cap ? b->face_cap : 1) * sizeof **arr);
		if (!*arr) abort();
		for (uint32_t i = 0; i < b->nface; i++)
			(*arr)[i] = no_idx;
	}
	return *arr;
}

static bool in_range(const uint32_t *idx, int n, uint32_t count)
{
	for (int k = 0; k < n; k++)
		if (idx[k] >= count)
			return false;
	return true;
}

bool mesh_add_face(struct mesh_builder *b, const uint32_t v[3], int ntex, const uint32_t *tex)
{
	if (!in_range(v, 3, b->verts.n) || (ntex != 0 && ntex != 1 && ntex != 3) ||
	    !in_range(tex, ntex, b->ntex))
		return false;
	face_reserve(b, b->nface + 1);
	uint32_t f = b->nface++;
	b->face[f] = (struct idx3){{v[0], v[1], v[2]}};
	if (b->face_n) b->face_n[f] = no_idx;
	if (b->face_uv) b->face_uv[f] = no_idx;
	if (b->face_tex) b->face_tex[f] = no_idx;
	if (ntex > 0) {
		struct idx3 t = no_idx;
		for (int k = 0; k < ntex; k++)
			t.i[k] = tex[k];
		face_opt(b, &b->face_tex)[f] = t;
	}
	return true;
}

bool mesh_set_face_normals(struct mesh_builder *b, uint32_t face, const uint32_t n[3])
{
	if (face >= b->nface || !in_range(n, 3, b->normals.n))
		return false;
	face_opt(b, &b->face_n)[face] = (struct idx3){{n[0], n[1], n[2]}};
	return true;
}

bool mesh_set_face_uvs(struct mesh_builder *b, uint32_t face, const uint32_t uv[3])
{
	if (face >= b->nface || !in_range(uv, 3, b->uvs.n))
		return false;
	face_opt(b, &b->face_uv)[face] = (struct idx3){{uv[0], uv[1], uv[2]}};
	return true;
}

void mesh_set_inside_vector(struct mesh_builder *b, vec3 dir) { b->inside = dir; }

/* ---- the shared data ---- */

/* A hierarchy node; the two children of an inner node are adjacent. */
struct mesh_node {
	double box[2][3]; /* [0] lower corner, [1] upper corner */
	uint32_t first;   /* leaf: first triangle; inner: left child (right = first + 1) */
	uint16_t count;   /* triangles in a leaf; 0 for an inner node */
	uint16_t axis;    /* inner: the split axis, for front-to-back order */
};

struct mesh_data {
	int refs;
	uint32_t nverts, nnormals, nuvs, ntex, ntris, nnodes;
	vec3 *verts;
	vec3 *normals;          /* unit */
	vec3 *uvs;              /* <u, v, 0> */
	struct texture **tex;   /* one reference each */
	struct idx3 *tri;       /* vertex indices, in hierarchy order */
	struct idx3 *tri_n;     /* normal indices (MESH_NONE: flat face) or NULL */
	struct idx3 *tri_uv;    /* uv indices (MESH_NONE: uv <0,0>) or NULL */
	struct idx3 *tri_tex;   /* texture indices: 1 (rest MESH_NONE), 3, or none; or NULL */
	struct mesh_node *nodes;
	struct aabb box;        /* object-space bounds of the kept triangles */
	double extent;          /* largest coordinate magnitude, for the traversal's padding */
	vec3 inside;
	bool has_inside;
};

struct mesh {
	struct object base;
	struct mesh_data *d; /* shared with every copy */
};

static void data_free(struct mesh_data *d)
{
	for (uint32_t i = 0; i < d->ntex; i++)
		texture_unref(d->tex[i]);
	free(d->tex);
	free(d->verts);
	free(d->normals);
	free(d->uvs);
	free(d->tri);
	free(d->tri_n);
	free(d->tri_uv);
	free(d->tri_tex);
	free(d->nodes);
	free(d);
}

/* ---- the hierarchy: binned SAH over triangle boxes ---- */

/* A triangle's box and centroid, in single precision: they only steer the
 * split choice. The node boxes are computed exactly from the vertices. */
struct bref {
	float lo[3], hi[3];
	uint32_t id;
};

struct bin {
	float lo[3], hi[3];
	uint32_t n;
};

struct build {
	struct bref *ref;
	struct mesh_node *nodes;
	uint32_t nnodes;
	const vec3 *verts;
	const struct idx3 *tri;
};

static float to_float(double x)
{
	return x > FLT_MAX ? FLT_MAX : x < -FLT_MAX ? -FLT_MAX : (float)x;
}

static inline float centroid(const struct bref *r, int a) { return 0.5f * r->lo[a] + 0.5f * r->hi[a]; }

static inline int bin_of(const struct bref *r, int a, float lo, float scale, int nb)
{
	int k = (int)((centroid(r, a) - lo) * scale);
	return k < 0 ? 0 : k >= nb ? nb - 1 : k;
}

static double half_area(const float lo[3], const float hi[3])
{
	double dx = (double)hi[0] - lo[0], dy = (double)hi[1] - lo[1], dz = (double)hi[2] - lo[2];
	if (dx < 0 || dy < 0 || dz < 0)
		return 0;
	return dx * dy + dy * dz + dz * dx;
}

static void box_from_vertices(struct build *b, struct mesh_node *nd, const struct bref *r, uint32_t n)
{
	double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
	for (uint32_t i = 0; i < n; i++)
		for (int k = 0; k < 3; k++) {
			vec3 p = b->verts[b->tri[r[i].id].i[k]];
			double c[3] = {p.x, p.y, p.z};
			for (int a = 0; a < 3; a++) {
				lo[a] = c[a] < lo[a] ? c[a] : lo[a];
				hi[a] = c[a] > hi[a] ? c[a] : hi[a];
			}
		}
	memcpy(nd->box[0], lo, sizeof lo);
	memcpy(nd->box[1], hi, sizeof hi);
}

/* Centroid bounds of a run of references. */
struct cbox {
	float lo[3], hi[3];
};

static void cbox_empty(struct cbox *c)
{
	for (int a = 0; a < 3; a++) {
		c->lo[a] = FLT_MAX;
		c->hi[a] = -FLT_MAX;
	}
}

static inline void cbox_add(struct cbox *c, const struct bref *r)
{
	for (int a = 0; a < 3; a++) {
		float x = centroid(r, a);
		c->lo[a] = x < c->lo[a] ? x : c->lo[a];
		c->hi[a] = x > c->hi[a] ? x : c->hi[a];
	}
}

static void build_node(struct build *b, uint32_t ni, uint32_t first, uint32_t n, int depth, const struct cbox *cb);

/* A subtree built on its own thread into its own node array (root at 0). */
struct subtree {
	struct build b;
	uint32_t first, n;
	int depth;
	struct cbox cb;
};

static void *subtree_main(void *arg)
{
	struct subtree *s = arg;
	build_node(&s->b, 0, s->first, s->n, s->depth, &s->cb);
	return NULL;
}

/* Build the children l (over nl references from first) and l + 1 (the nr
 * after them): the left one on another thread, the right one here. The
 * references of the two are disjoint ranges, so only the node arrays need
 * keeping apart; the left one's nodes are appended afterwards with their
 * child indices moved. The result is the tree the sequential build makes,
 * with its nodes in another order. */
static void build_pair_parallel(struct build *b, uint32_t l, uint32_t first, uint32_t nl, uint32_t nr, int depth,
                                const struct cbox *lc, const struct cbox *rc)
{
	struct subtree s = {.b = *b, .first = first, .n = nl, .depth = depth, .cb = *lc};
	s.b.nodes = malloc((2 * (size_t)nl - 1) * sizeof *s.b.nodes);
	if (!s.b.nodes) abort();
	s.b.nnodes = 1;
	pthread_t th;
	bool threaded = pthread_create(&th, NULL, subtree_main, &s) == 0;
	if (!threaded)
		subtree_main(&s);
	build_node(b, l + 1, first + nl, nr, depth, rc);
	if (threaded)
		pthread_join(th, NULL);
	/* Sub-node k >= 1 goes to off + k - 1; node 0 to l. */
	uint32_t off = b->nnodes;
	for (uint32_t k = 0; k < s.b.nnodes; k++) {
		struct mesh_node nd = s.b.nodes[k];
		if (nd.count == 0)
			nd.first = off + nd.first - 1;
		b->nodes[k == 0 ? l : off + k - 1] = nd;
	}
	b->nnodes += s.b.nnodes - 1;
	free(s.b.nodes);
}

/* Build node ni over ref[first, first+n), whose centroids lie in *cb.
 * Wald's binned SAH (2007): the references are binned along the axis
 * where their centroids spread most, the best of the bin boundaries is
 * taken if it beats a leaf (traversal cost 1, triangle cost 1), and the
 * partition computes the children's centroid bounds on the way. */
static void build_node(struct build *b, uint32_t ni, uint32_t first, uint32_t n, int depth, const struct cbox *cb)
{
	struct bref *r = b->ref + first;
	int axis = 0;
	for (int a = 1; a < 3; a++)
		if (cb->hi[a] - cb->lo[a] > cb->hi[axis] - cb->lo[axis])
			axis = a;
	float clo = cb->lo[axis], ext = cb->hi[axis] - clo;
	int nb = n < BINS ? (int)n : BINS; /* few bins for small nodes: per-bin work would dominate */
	float scale = ext > 0 ? (float)nb / ext : 0;
	if (!isfinite(scale))
		scale = 0; /* centroids a few denormals apart: no bins */

	int split = 0;
	double best = INFINITY;
	if (scale > 0 && depth < DEPTH_MAX && n > LEAF_MIN) {
		struct bin bins[BINS];
		for (int k = 0; k < nb; k++) {
			bins[k].n = 0;
			for (int c = 0; c < 3; c++) {
				bins[k].lo[c] = FLT_MAX;
				bins[k].hi[c] = -FLT_MAX;
			}
		}
		for (uint32_t i = 0; i < n; i++) {
			struct bin *bn = &bins[bin_of(&r[i], axis, clo, scale, nb)];
			bn->n++;
			for (int c = 0; c < 3; c++) {
				bn->lo[c] = r[i].lo[c] < bn->lo[c] ? r[i].lo[c] : bn->lo[c];
				bn->hi[c] = r[i].hi[c] > bn->hi[c] ? r[i].hi[c] : bn->hi[c];
			}
		}
		/* Right-hand sides of each boundary, then a sweep from the left;
		 * the last right-hand box is the whole node's. */
		double rarea[BINS];
		uint32_t rn[BINS];
		float lo[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, hi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
		uint32_t cnt = 0;
		for (int k = nb - 1; k >= 0; k--) {
			for (int c = 0; c < 3; c++) {
				lo[c] = bins[k].lo[c] < lo[c] ? bins[k].lo[c] : lo[c];
				hi[c] = bins[k].hi[c] > hi[c] ? bins[k].hi[c] : hi[c];
			}
			cnt += bins[k].n;
			rarea[k] = half_area(lo, hi);
			rn[k] = cnt;
		}
		double area = half_area(lo, hi);
		if (!(area > 0))
			area = 1;
		for (int c = 0; c < 3; c++) {
			lo[c] = FLT_MAX;
			hi[c] = -FLT_MAX;
		}
		cnt = 0;
		for (int k = 0; k < nb - 1; k++) {
			for (int c = 0; c < 3; c++) {
				lo[c] = bins[k].lo[c] < lo[c] ? bins[k].lo[c] : lo[c];
				hi[c] = bins[k].hi[c] > hi[c] ? bins[k].hi[c] : hi[c];
			}
			cnt += bins[k].n;
			if (cnt == 0 || rn[k + 1] == 0)
				continue;
			double cost = 1 + (half_area(lo, hi) * cnt + rarea[k + 1] * rn[k + 1]) / area;
			if (cost < best) {
				best = cost;
				split = k + 1;
			}
		}
	}

	struct mesh_node *nd = &b->nodes[ni];
	if (n <= LEAF_MAX && (split == 0 || best >= (double)n)) {
		nd->first = first;
		nd->count = (uint16_t)n;
		nd->axis = 0;
		box_from_vertices(b, nd, r, n);
		return;
	}
	struct cbox lc, rc;
	cbox_empty(&lc);
	cbox_empty(&rc);
	uint32_t mid = 0;
	if (split > 0) {
		uint32_t i = 0, j = n;
		while (i < j) {
			if (bin_of(&r[i], axis, clo, scale, nb) < split) {
				cbox_add(&lc, &r[i]);
				i++;
			} else {
				cbox_add(&rc, &r[i]);
				struct bref t = r[i];
				r[i] = r[--j];
				r[j] = t;
			}
		}
		mid = i;
	}
	if (mid == 0 || mid == n) {
		/* All centroids equal, or too deep: halve the list. */
		mid = n / 2;
		cbox_empty(&lc);
		cbox_empty(&rc);
		for (uint32_t i = 0; i < n; i++)
			cbox_add(i < mid ? &lc : &rc, &r[i]);
	}
	uint32_t l = b->nnodes;
	b->nnodes += 2;
	nd->first = l;
	nd->count = 0;
	nd->axis = (uint16_t)axis;
	if (n >= PAR_MIN && depth < PAR_DEPTH)
		build_pair_parallel(b, l, first, mid, n - mid, depth + 1, &lc, &rc);
	else {
		build_node(b, l, first, mid, depth + 1, &lc);
		build_node(b, l + 1, first + mid, n - mid, depth + 1, &rc);
	}
	nd = &b->nodes[ni];
	const struct mesh_node *L = &b->nodes[l], *R = &b->nodes[l + 1];
	for (int a = 0; a < 3; a++) {
		nd->box[0][a] = L->box[0][a] < R->box[0][a] ? L->box[0][a] : R->box[0][a];
		nd->box[1][a] = L->box[1][a] > R->box[1][a] ? L->box[1][a] : R->box[1][a];
	}
}

/* Reorder a per-face array to the hierarchy's order. */
static void permute(struct idx3 **arr, const struct bref *ref, uint32_t n)
{
	if (!*arr)
		return;
	struct idx3 *out = malloc((size_t)n * sizeof *out);
	if (!out) abort();
	for (uint32_t i = 0; i < n; i++)
		out[i] = (*arr)[ref[i].id];
	free(*arr);
	*arr = out;
}

static void build_hierarchy(struct mesh_data *d)
{
	uint32_t n = d->ntris;
	struct build b = {.verts = d->verts, .tri = d->tri};
	b.ref = malloc((size_t)n * sizeof *b.ref);
	b.nodes = malloc((size_t)(2 * (uint64_t)n - 1) * sizeof *b.nodes);
	if (!b.ref || !b.nodes) abort();
	for (uint32_t i = 0; i < n; i++) {
		struct bref *r = &b.ref[i];
		for (int a = 0; a < 3; a++) {
			r->lo[a] = FLT_MAX;
			r->hi[a] = -FLT_MAX;
		}
		for (int k = 0; k < 3; k++) {
			vec3 p = d->verts[d->tri[i].i[k]];
			float c[3] = {to_float(p.x), to_float(p.y), to_float(p.z)};
			for (int a = 0; a < 3; a++) {
				r->lo[a] = c[a] < r->lo[a] ? c[a] : r->lo[a];
				r->hi[a] = c[a] > r->hi[a] ? c[a] : r->hi[a];
			}
		}
		r->id = i;
	}
	struct cbox cb;
	cbox_empty(&cb);
	for (uint32_t i = 0; i < n; i++)
		cbox_add(&cb, &b.ref[i]);
	b.nnodes = 1;
	build_node(&b, 0, 0, n, 0, &cb);
	permute(&d->tri, b.ref, n);
	permute(&d->tri_n, b.ref, n);
	permute(&d->tri_uv, b.ref, n);
	permute(&d->tri_tex, b.ref, n);
	free(b.ref);
	struct mesh_node *nodes = realloc(b.nodes, (size_t)b.nnodes * sizeof *nodes);
	d->nodes = nodes ? nodes : b.nodes;
	d->nnodes = b.nnodes;
}

static struct idx3 *copy_idx(const struct idx3 *a, uint32_t n)
{
	struct idx3 *c = malloc((size_t)(n ? n : 1) * sizeof *c);
	if (!c) abort();
	memcpy(c, a, (size_t)n * sizeof *c);
	return c;
}

/* Take the builder's arrays, apply mesh2's default indices, drop degenerate
 * faces, and build the hierarchy. */
static struct mesh_data *data_new(struct mesh_builder *b)
{
	struct mesh_data *d = calloc(1, sizeof *d);
	if (!d) abort();
	d->refs = 1;
	d->nverts = b->verts.n;
	d->verts = resize(b->verts.v, b->verts.n, sizeof *d->verts);
	d->nnormals = b->normals.n;
	d->normals = resize(b->normals.v, b->normals.n, sizeof *d->normals);
	d->nuvs = b->uvs.n;
	d->uvs = resize(b->uvs.v, b->uvs.n, sizeof *d->uvs);
	d->ntex = b->ntex;
	d->tex = b->tex;
	d->tri = b->face;
	d->tri_n = b->face_n;
	d->tri_uv = b->face_uv;
	d->tri_tex = b->face_tex;
	uint32_t n = b->nface;
	enum mesh_kind kind = b->kind;
	free(b->verts.slot);
	free(b->normals.slot);
	free(b->uvs.slot);
	free(b);

	if (kind == MESH_KIND_MESH2 && n > 0) {
		if (!d->tri_n && d->nnormals > 0 && d->nnormals == d->nverts)
			d->tri_n = copy_idx(d->tri, n);
		if (!d->tri_uv && d->nuvs > 0 && d->nuvs == d->nverts)
			d->tri_uv = copy_idx(d->tri, n);
	}

	/* POV-Ray's mesh2 extents include the corners of the degenerate faces
	 * it drops (measured with max_extent: a face <3,4,4> reaches vertex
	 * 4); its mesh extents do not. */
	struct aabb dropped = aabb_empty();
	uint32_t kept = 0;
	for (uint32_t i = 0; i < n; i++) {
		const struct idx3 *f = &d->tri[i];
		if (tri_degenerate(d->verts[f->i[0]], d->verts[f->i[1]], d->verts[f->i[2]])) {
			if (kind == MESH_KIND_MESH2)
				for (int k = 0; k < 3; k++)
					dropped = aabb_add_point(dropped, d->verts[f->i[k]]);
			continue;
		}
		d->tri[kept] = d->tri[i];
		if (d->tri_n) d->tri_n[kept] = d->tri_n[i];
		if (d->tri_uv) d->tri_uv[kept] = d->tri_uv[i];
		if (d->tri_tex) d->tri_tex[kept] = d->tri_tex[i];
		kept++;
	}
	d->ntris = kept;
	d->tri = resize(d->tri, kept, sizeof *d->tri);
	d->tri_n = resize(d->tri_n, kept, sizeof *d->tri_n);
	d->tri_uv = resize(d->tri_uv, kept, sizeof *d->tri_uv);
	d->tri_tex = resize(d->tri_tex, kept, sizeof *d->tri_tex);

	d->box = dropped;
	if (kept > 0) {
		build_hierarchy(d);
		const struct mesh_node *root = &d->nodes[0];
		struct aabb tb = {v3(root->box[0][0], root->box[0][1], root->box[0][2]),
		                  v3(root->box[1][0], root->box[1][1], root->box[1][2])};
		d->box = aabb_union(d->box, tb);
	}
	if (!aabb_is_finite(d->box))
		d->box = (struct aabb){{0, 0, 0}, {0, 0, 0}};
	d->extent = fmax(v3_maxabs(d->box.lo), v3_maxabs(d->box.hi));
	return d;
}

/* ---- traversal ---- */

enum walk_mode {
	WALK_CLOSEST, /* the nearest hit, in out[0] */
	WALK_ALL,     /* the nearest `max` hits, sorted, in out[] */
	WALK_COUNT,   /* how many crossings */
};

struct walk {
	struct tri_ray tr;
	double inv[3];        /* 1 / direction */
	double org_near[3];   /* the origin moved so that the near slab planes are padded */
	double org_far[3];    /* ... and the far ones */
	int near[3];          /* which corner holds the near plane: 0 lower, 1 upper */
	enum walk_mode mode;
	double tmin, tmax;
	struct hit *out;
	int n, max;
	size_t count;
};

/* The box test must keep every node whose triangles the triangle test can
 * hit. That test works on vertices sheared relative to the origin, whose
 * rounding can move a triangle by a few ulps of the largest coordinate
 * involved; so the boxes are padded by 64 ulps of that magnitude (the
 * origin's or the mesh's), which also covers the slab test's own rounding. */
static bool walk_init(struct walk *w, const struct mesh_data *d, const struct ray *r, enum walk_mode mode,
                      double tmin, double tmax)
{
	if (d->ntris == 0 || !tri_ray_init(&w->tr, r))
		return false;
	double o[3] = {r->org.x, r->org.y, r->org.z}, dir[3] = {r->dir.x, r->dir.y, r->dir.z};
	double m = fmax(d->extent, v3_maxabs(r->org));
	if (!isfinite(m))
		return false;
	double pad = 64 * DBL_EPSILON * m;
	for (int a = 0; a < 3; a++) {
		w->inv[a] = 1.0 / dir[a];
		w->near[a] = signbit(dir[a]) ? 1 : 0;
		double s = w->near[a] ? -pad : pad;
		w->org_near[a] = o[a] + s;
		w->org_far[a] = o[a] - s;
	}
	w->mode = mode;
	w->tmin = tmin;
	w->tmax = tmax;
	w->n = 0;
	w->count = 0;
	return true;
}

/* Slab test of a node's padded box against (tmin, tmax). A NaN from a
 * plane through the origin parallel to the ray does not narrow the range. */
static inline bool box_hit(const struct mesh_node *nd, const struct walk *w, double *entry)
{
	double t0 = w->tmin, t1 = w->tmax;
	for (int a = 0; a < 3; a++) {
		double tn = (nd->box[w->near[a]][a] - w->org_near[a]) * w->inv[a];
		double tf = (nd->box[1 - w->near[a]][a] - w->org_far[a]) * w->inv[a];
		if (tn > t0) t0 = tn;
		if (tf < t1) t1 = tf;
	}
	*entry = t0;
	return t0 <= t1;
}

static void record(struct walk *w, uint32_t tri, const struct tri_hit *th)
{
	struct hit h = {.t = th->t, .part = (int)tri, .u = th->u, .v = th->v};
	switch (w->mode) {
	case WALK_CLOSEST: /* h->obj is the caller's */
		w->out[0].t = h.t;
		w->out[0].part = h.part;
		w->out[0].u = h.u;
		w->out[0].v = h.v;
		w->n = 1;
		w->tmax = th->t;
		break;
	case WALK_ALL: {
		int i = w->n < w->max ? w->n++ : w->max - 1;
		while (i > 0 && w->out[i - 1].t > h.t) {
			w->out[i] = w->out[i - 1];
			i--;
		}
		w->out[i] = h;
		if (w->n == w->max)
			w->tmax = w->out[w->max - 1].t;
		break;
	}
	case WALK_COUNT:
		w->count++;
		break;
	}
}

/* Depth first, nearer child first. Both children's boxes are tested at
 * their parent and kept with their entry distance, so a subtree that
 * starts beyond the closest hit found meanwhile is dropped unvisited. */
static void walk(const struct mesh_data *d, struct walk *w)
{
	struct {
		uint32_t node;
		double t;
	} stack[STACK_MAX];
	int sp = 0;
	double t0;
	if (!box_hit(&d->nodes[0], w, &t0))
		return;
	stack[sp].node = 0;
	stack[sp++].t = t0;
	while (sp > 0) {
		sp--;
		if (stack[sp].t > w->tmax)
			continue;
		const struct mesh_node *nd = &d->nodes[stack[sp].node];
		if (!nd->count) {
			double ta, tb;
			bool ha = box_hit(&d->nodes[nd->first], w, &ta);
			bool hb = box_hit(&d->nodes[nd->first + 1], w, &tb);
			if (ha && hb) {
				bool a_first = ta <= tb;
				stack[sp].node = a_first ? nd->first + 1 : nd->first;
				stack[sp++].t = a_first ? tb : ta;
				stack[sp].node = a_first ? nd->first : nd->first + 1;
				stack[sp++].t = a_first ? ta : tb;
			} else if (ha || hb) {
				stack[sp].node = ha ? nd->first : nd->first + 1;
				stack[sp++].t = ha ? ta : tb;
			}
			continue;
		}
		{
			for (uint32_t i = nd->first; i < nd->first + nd->count; i++) {
				const struct idx3 *f = &d->tri[i];
				struct tri_hit th;
				if (tri_intersect(&w->tr, d->verts[f->i[0]], d->verts[f->i[1]], d->verts[f->i[2]],
				                  w->tmin, w->tmax, &th))
					record(w, i, &th);
			}
		}
	}
}

/* ---- the object ---- */

static const struct mesh_data *data_of(const struct object *o) { return ((const struct mesh *)o)->d; }

static bool mesh_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct mesh_data *d = data_of(o);
	struct walk w;
	if (!walk_init(&w, d, r, WALK_CLOSEST, tmin, tmax))
		return false;
	w.out = h;
	walk(d, &w);
	return w.n > 0;
}

static int mesh_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	const struct mesh_data *d = data_of(o);
	struct walk w;
	if (max < 1 || !walk_init(&w, d, r, WALK_ALL, tmin, tmax))
		return 0;
	w.out = out;
	w.max = max;
	walk(d, &w);
	for (int i = 0; i < w.n; i++)
		out[i].obj = o;
	return w.n;
}

/* POV-Ray's solid mesh: with an inside_vector, p is inside when a ray from
 * it along that vector crosses the mesh an odd number of times. */
static bool mesh_inside(const struct object *o, vec3 p)
{
	const struct mesh_data *d = data_of(o);
	struct walk w;
	struct ray r = {p, d->inside};
	if (!d->has_inside || !walk_init(&w, d, &r, WALK_COUNT, 0, INFINITY))
		return false;
	walk(d, &w);
	return w.count & 1;
}

/* The face and barycentrics of a hit; without a valid hit record, the face
 * whose centroid is nearest to p (a fallback no renderer path should need). */
static uint32_t face_of(const struct mesh_data *d, vec3 p, const struct hit *h, double *u, double *v)
{
	if (h && h->part >= 0 && (uint32_t)h->part < d->ntris) {
		*u = h->u;
		*v = h->v;
		return (uint32_t)h->part;
	}
	uint32_t best = 0;
	double bd = INFINITY;
	for (uint32_t i = 0; i < d->ntris; i++) {
		const struct idx3 *f = &d->tri[i];
		vec3 c = v3_scale(v3_add(d->verts[f->i[0]], v3_add(d->verts[f->i[1]], d->verts[f->i[2]])), 1.0 / 3);
		vec3 e = v3_sub(c, p);
		if (v3_dot(e, e) < bd) {
			bd = v3_dot(e, e);
			best = i;
		}
	}
	const struct idx3 *f = &d->tri[best];
	tri_barycentric(d->verts[f->i[0]], d->verts[f->i[1]], d->verts[f->i[2]], p, u, v);
	return best;
}

/* Interpolate the three entries idx of list at weights (1-u-v, u, v). */
static vec3 interpolate(const vec3 *list, const struct idx3 *idx, double u, double v)
{
	vec3 r = v3_scale(list[idx->i[0]], 1 - u - v);
	r = v3_madd(r, list[idx->i[1]], u);
	return v3_madd(r, list[idx->i[2]], v);
}

/* The flat normal (c - a) x (b - a) (POV-Ray's orientation, as for
 * triangle), or for a face with normals the unit
 * vertex normals interpolated linearly (POV-Ray's smooth triangles), the
 * flat one where they cancel. */
static vec3 mesh_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct mesh_data *d = data_of(o);
	if (d->ntris == 0)
		return v3(0, 1, 0);
	double u, v;
	uint32_t i = face_of(d, p, h, &u, &v);
	const struct idx3 *f = &d->tri[i];
	vec3 a = d->verts[f->i[0]];
	vec3 flat = v3_cross(v3_sub(d->verts[f->i[2]], a), v3_sub(d->verts[f->i[1]], a));
	if (d->tri_n && d->tri_n[i].i[0] != MESH_NONE) {
		vec3 n = interpolate(d->normals, &d->tri_n[i], u, v);
		double nn = v3_dot(n, n);
		if (nn > 0 && isfinite(nn))
			return n;
	}
	return flat;
}

static struct aabb mesh_bounds(const struct object *o) { return data_of(o)->box; }

/* uv_mapping: the face's uv vectors interpolated; <0,0> for a face without
 * them, as POV-Ray does. */
static bool mesh_uv(const struct object *o, vec3 p, const struct hit *h, double uv[2])
{
	const struct mesh_data *d = data_of(o);
	uv[0] = uv[1] = 0;
	if (d->ntris == 0 || !d->tri_uv)
		return true;
	double u, v;
	uint32_t i = face_of(d, p, h, &u, &v);
	if (d->tri_uv[i].i[0] != MESH_NONE) {
		vec3 r = interpolate(d->uvs, &d->tri_uv[i], u, v);
		uv[0] = r.x;
		uv[1] = r.y;
	}
	return true;
}

static struct texture *mesh_texture_at(const struct object *o, const struct hit *h)
{
	const struct mesh_data *d = data_of(o);
	if (!d->tri_tex || !h || h->part < 0 || (uint32_t)h->part >= d->ntris)
		return NULL;
	uint32_t t = d->tri_tex[h->part].i[0];
	return t == MESH_NONE ? NULL : d->tex[t];
}

int mesh_textures_at(const struct object *o, const struct hit *h, struct texture *tex[3], double w[3])
{
	const struct mesh_data *d = data_of(o);
	if (!d->tri_tex || !h || h->part < 0 || (uint32_t)h->part >= d->ntris)
		return 0;
	const struct idx3 *t = &d->tri_tex[h->part];
	if (t->i[0] == MESH_NONE)
		return 0;
	w[0] = 1 - h->u - h->v;
	w[1] = h->u;
	w[2] = h->v;
	tex[0] = d->tex[t->i[0]];
	if (t->i[1] == MESH_NONE)
		return 1;
	tex[1] = d->tex[t->i[1]];
	tex[2] = d->tex[t->i[2]];
	return 3;
}

/* The textures op: the mesh's texture list. */
static size_t mesh_textures(const struct object *o, struct texture *const **tex)
{
	const struct mesh_data *d = data_of(o);
	*tex = d->tex;
	return d->ntex;
}

static struct object *mesh_copy(const struct object *o)
{
	struct mesh *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct mesh *)o;
	c->d->refs++;
	return &c->base;
}

static void mesh_destroy(struct object *o)
{
	struct mesh_data *d = ((struct mesh *)o)->d;
	if (--d->refs == 0)
		data_free(d);
}

static const struct object_ops mesh_ops = {
	.textures = mesh_textures,
	.name = "mesh",
	.intersect = mesh_intersect,
	.all_hits = mesh_all_hits,
	.inside = mesh_inside,
	.normal = mesh_normal,
	.bounds = mesh_bounds,
	.uv = mesh_uv,
	.texture_at = mesh_texture_at,
	.copy = mesh_copy,
	.destroy = mesh_destroy,
};

struct object *mesh_new(struct mesh_builder *b, struct srcpos pos)
{
	vec3 inside = b->inside;
	struct mesh *m = calloc(1, sizeof *m);
	if (!m) abort();
	object_init(&m->base, &mesh_ops, pos);
	m->d = data_new(b);
	m->d->inside = inside;
	m->d->has_inside = v3_dot(inside, inside) > 0 && isfinite(v3_dot(inside, inside));
	return &m->base;
}

void mesh_get_stats(const struct object *o, struct mesh_stats *st)
{
	const struct mesh_data *d = data_of(o);
	size_t per_face = sizeof(struct idx3) * (1 + !!d->tri_n + !!d->tri_uv + !!d->tri_tex);
	st->triangles = d->ntris;
	st->vertices = d->nverts;
	st->nodes = d->nnodes;
	st->bytes = sizeof *d + (size_t)d->nverts * sizeof *d->verts + (size_t)d->nnormals * sizeof *d->normals +
	            (size_t)d->nuvs * sizeof *d->uvs + (size_t)d->ntex * sizeof *d->tex +
	            (size_t)d->ntris * per_face + (size_t)d->nnodes * sizeof *d->nodes;
	st->refs = d->refs;
	st->data = d;
}

void mesh_triangle(const struct object *o, size_t i, vec3 corner[3])
{
	const struct mesh_data *d = data_of(o);
	for (int k = 0; k < 3; k++)
		corner[k] = d->verts[d->tri[i].i[k]];
}

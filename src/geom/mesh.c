/* mesh.c: triangle meshes (see mesh.h): the builder, the shared data with
 * its bounding volume hierarchy, and the object's operations. */
#include "geom/mesh.h"
#include "geom/tri.h"
#include "math/hash.h"

#include <float.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

enum {
	BINS = 16,         /* SAH bins per axis */
	LEAF_MIN = 2,      /* leaves hold at most this many triangles */
	CLUSTER_MAX = 8,   /* triangles per cluster at most (see the hierarchy) */
	DEPTH_MAX = 64,    /* past this depth, upper nodes are split at the middle of their list */
	PAR_MIN = 1 << 14, /* this many clusters (triangles, for the clusters' subtrees) are built on
	                    * two threads... */
	PAR_DEPTH = 2,     /* ...down to this depth (at most 4 upper subtrees at once) */
	STACK_MAX = 128,   /* > DEPTH_MAX + 32 + CLUSTER_MAX: the deepest tree a 2^32 list can give */
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
	uint32_t *decl;         /* [i]: the hierarchy index of kept face i in declaration order */
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
	free(d->decl);
	free(d->nodes);
	free(d);
}

/* ---- the hierarchy ----
 *
 * Built in two parts, after Pantaleoni and Luebke's HLBVH (2010): the
 * triangles are sorted along a Morton curve through their centroids and
 * cut, at the curve's own octree boundaries, into clusters of at most
 * CLUSTER_MAX neighbouring triangles; inside a cluster the octree
 * boundaries are the splits. Over the clusters, weighted by their
 * triangle counts, a binned surface area heuristic (Wald 2007) builds the
 * upper levels, where the choice of split matters most. Sorting, the
 * clusters and their subtrees cost a few passes over the triangles; only
 * the upper part, over several times fewer items, pays for binning.
 *
 * The node array holds the upper tree first (a tree over k clusters has
 * 2k - 1 nodes, so each subtree's place is known before it is built), then
 * each cluster's nodes below its root in a range of its own. Triangles are
 * stored in curve order, which is also the order of every leaf. */

/* Four floats at once: SSE where the compiler targets it (every x86-64),
 * plain loops elsewhere. Boxes use lanes 0-2; lane 3 is either ignored
 * (min/max) or cleared before arithmetic. */
#if defined(__SSE2__)
typedef __m128 f4;
static inline f4 f4_load(const float *p) { return _mm_load_ps(p); }
static inline void f4_store(float *p, f4 a) { _mm_store_ps(p, a); }
static inline f4 f4_min(f4 a, f4 b) { return _mm_min_ps(a, b); }
static inline f4 f4_max(f4 a, f4 b) { return _mm_max_ps(a, b); }
static inline f4 f4_add(f4 a, f4 b) { return _mm_add_ps(a, b); }
static inline f4 f4_splat(float x) { return _mm_set1_ps(x); }
static inline f4 f4_xyz(f4 a) { return _mm_and_ps(a, _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1))); }
#else
typedef struct {
	float v[4];
} f4;
static inline f4 f4_load(const float *p) { f4 r; memcpy(r.v, p, sizeof r.v); return r; }
static inline void f4_store(float *p, f4 a) { memcpy(p, a.v, sizeof a.v); }
static inline f4 f4_min(f4 a, f4 b) { for (int i = 0; i < 4; i++) a.v[i] = a.v[i] < b.v[i] ? a.v[i] : b.v[i]; return a; }
static inline f4 f4_max(f4 a, f4 b) { for (int i = 0; i < 4; i++) a.v[i] = a.v[i] > b.v[i] ? a.v[i] : b.v[i]; return a; }
static inline f4 f4_add(f4 a, f4 b) { for (int i = 0; i < 4; i++) a.v[i] += b.v[i]; return a; }
static inline f4 f4_splat(float x) { return (f4){{x, x, x, x}}; }
static inline f4 f4_xyz(f4 a) { a.v[3] = 0; return a; }
#endif

/* A cluster as the upper build sees it: its box in single precision (it
 * only steers the split; node boxes are exact), f[0..2] the lower corner,
 * f[3] the cluster's index (its bits), f[4..6] the upper corner, f[7] its
 * triangle count. Centroids are kept doubled (lo + hi). */
struct cref {
	_Alignas(16) float f[8];
};

static inline uint32_t cref_id(const struct cref *r)
{
	uint32_t id;
	memcpy(&id, &r->f[3], sizeof id);
	return id;
}

/* A box over lanes 0-2: cluster boxes or doubled centroids. */
struct fbox {
	_Alignas(16) float lo[4], hi[4];
};

struct bin {
	struct fbox box;  /* the clusters' boxes */
	struct fbox cent; /* their doubled centroids */
	uint32_t n;       /* their triangles */
};

struct build {
	struct mesh_node *nodes;
	const vec3 *verts;
	const struct idx3 *tri;     /* in curve order */
	const uint64_t *code;       /* the triangles' Morton codes, ascending */
	const uint32_t *cfirst;     /* cluster k: triangles cfirst[k] .. cfirst[k+1] - 1 */
	const struct mesh_node *croot; /* each cluster's root */
	struct cref *cref;
};

static void fbox_empty(struct fbox *b)
{
	f4_store(b->lo, f4_splat(FLT_MAX));
	f4_store(b->hi, f4_splat(-FLT_MAX));
}

static inline void fbox_join(struct fbox *b, const struct fbox *o)
{
	f4_store(b->lo, f4_min(f4_load(b->lo), f4_load(o->lo)));
	f4_store(b->hi, f4_max(f4_load(b->hi), f4_load(o->hi)));
}

/* Half the surface area of a box that is not empty. */
static inline float half_area(const struct fbox *b)
{
	float dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
	return dx * dy + dy * dz + dz * dx;
}

/* A coordinate in single precision, within a quarter of the float range so
 * that doubled centroids and their spreads stay finite. */
static float to_float(double x)
{
	const double lim = FLT_MAX / 4;
	return (float)(x > lim ? lim : x < -lim ? -lim : x);
}

/* Where a doubled centroid falls on `axis`, in bins: at least 0, since the
 * centroid box's low side is exact, and at most nb. */
static inline float bin_pos(const struct cref *r, int axis, float lo, float scale)
{
	return (r->f[axis] + r->f[4 + axis] - lo) * scale;
}

/* Its bin: the position truncated, the upper end in the last bin. An item
 * is left of boundary `split` exactly when bin_pos < split, so the
 * partition needs no conversion and agrees with the binning. */
static inline int bin_of(const struct cref *r, int axis, float lo, float scale, int nb)
{
	int k = (int)bin_pos(r, axis, lo, scale);
	return k < nb - 1 ? k : nb - 1;
}

/* The doubled centroids' box of n clusters, by scanning them. */
static void cent_scan(struct fbox *c, const struct cref *r, uint32_t n)
{
	f4 lo = f4_splat(FLT_MAX), hi = f4_splat(-FLT_MAX);
	for (uint32_t i = 0; i < n; i++) {
		f4 x = f4_add(f4_xyz(f4_load(r[i].f)), f4_xyz(f4_load(r[i].f + 4)));
		lo = f4_min(lo, x);
		hi = f4_max(hi, x);
	}
	f4_store(c->lo, lo);
	f4_store(c->hi, hi);
}

static void node_join(struct mesh_node *nd, const struct mesh_node *L, const struct mesh_node *R)
{
	for (int a = 0; a < 3; a++) {
		nd->box[0][a] = L->box[0][a] < R->box[0][a] ? L->box[0][a] : R->box[0][a];
		nd->box[1][a] = L->box[1][a] > R->box[1][a] ? L->box[1][a] : R->box[1][a];
	}
}

/* ---- sorting along the curve ---- */

/* The 21 low bits of x spread to every third bit. */
static uint64_t spread3(uint64_t x)
{
	x &= 0x1fffff;
	x = (x | x << 32) & 0x1f00000000ffffULL;
	x = (x | x << 16) & 0x1f0000ff0000ffULL;
	x = (x | x << 8) & 0x100f00f00f00f00fULL;
	x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
	x = (x | x << 2) & 0x1249249249249249ULL;
	return x;
}

/* Where the range code[first, first+n) splits at its highest differing
 * bit (a boundary of the curve's octree), as an offset in 1..n-1; the
 * middle when all codes are equal. *bit: that bit, or -1. */
static uint32_t curve_split(const uint64_t *code, uint32_t first, uint32_t n, int *bit)
{
	uint64_t a = code[first], b = code[first + n - 1];
	if (a == b) {
		*bit = -1;
		return n / 2;
	}
#if defined(__GNUC__)
	int k = 63 - __builtin_clzll(a ^ b);
#else
	int k = 63;
	while (!((a ^ b) >> k & 1))
		k--;
#endif
	*bit = k;
	uint64_t v = b >> k << k; /* the first code with bit k set */
	uint32_t lo = 0, hi = n - 1;  /* code[first+lo] < v <= code[first+hi] */
	while (hi - lo > 1) {
		uint32_t m = lo + (hi - lo) / 2;
		if (code[first + m] < v)
			lo = m;
		else
			hi = m;
	}
	return hi;
}

/* Cut code[first, first+n) at octree boundaries into clusters of at most
 * CLUSTER_MAX triangles, appending each cluster's first index to out. */
static void make_clusters(const uint64_t *code, uint32_t first, uint32_t n, uint32_t *out, uint32_t *nout)
{
	while (n > CLUSTER_MAX) {
		int bit;
		uint32_t mid = curve_split(code, first, n, &bit);
		make_clusters(code, first, mid, out, nout);
		first += mid;
		n -= mid;
	}
	out[(*nout)++] = first;
}

/* ---- a cluster's subtree ---- */

/* Component-wise minimum and maximum (plain comparisons: the vertices are
 * finite, and unlike fmin these compile to single instructions). */
static inline vec3 vmin(vec3 a, vec3 b) { return v3(a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z); }
static inline vec3 vmax(vec3 a, vec3 b) { return v3(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z); }

static void leaf_box(const struct build *b, struct mesh_node *nd, uint32_t first, uint32_t n)
{
	const struct idx3 *t = &b->tri[first];
	vec3 lo = b->verts[t->i[0]], hi = lo;
	for (uint32_t i = 0; i < n; i++, t++)
		for (int k = 0; k < 3; k++) {
			vec3 p = b->verts[t->i[k]];
			lo = vmin(lo, p);
			hi = vmax(hi, p);
		}
	nd->box[0][0] = lo.x;
	nd->box[0][1] = lo.y;
	nd->box[0][2] = lo.z;
	nd->box[1][0] = hi.x;
	nd->box[1][1] = hi.y;
	nd->box[1][2] = hi.z;
}

/* Fill *nd over triangles [first, first+n), split at the curve's octree
 * boundaries down to leaves of LEAF_MIN; children go at *next and on. */
static void build_cluster(const struct build *b, struct mesh_node *nd, uint32_t first, uint32_t n, uint32_t *next)
{
	if (n <= LEAF_MIN) {
		nd->first = first;
		nd->count = (uint16_t)n;
		nd->axis = 0;
		leaf_box(b, nd, first, n);
		return;
	}
	int bit;
	uint32_t mid = curve_split(b->code, first, n, &bit);
	uint32_t l = *next;
	*next += 2;
	nd->first = l;
	nd->count = 0;
	nd->axis = (uint16_t)(bit < 0 ? 0 : bit % 3);
	build_cluster(b, &b->nodes[l], first, mid, next);
	build_cluster(b, &b->nodes[l + 1], first + mid, n - mid, next);
	node_join(nd, &b->nodes[l], &b->nodes[l + 1]);
}

/* How many leaves build_cluster makes over [first, first+n). */
static uint32_t cluster_leaves(const uint64_t *code, uint32_t first, uint32_t n)
{
	if (n <= LEAF_MIN)
		return 1;
	int bit;
	uint32_t mid = curve_split(code, first, n, &bit);
	return cluster_leaves(code, first, mid) + cluster_leaves(code, first + mid, n - mid);
}

/* Clusters [k0, k1): with `count`, the number of nodes each one's subtree
 * needs below its root, into cnode[k]; otherwise the subtrees, below their
 * roots (kept in croot), each in the node range from cnode[k] on. */
struct cluster_job {
	const struct build *b;
	struct mesh_node *croot;
	uint32_t *cnode;
	uint32_t k0, k1;
	bool count;
};

static void *cluster_job_main(void *arg)
{
	struct cluster_job *j = arg;
	const struct build *b = j->b;
	for (uint32_t k = j->k0; k < j->k1; k++) {
		uint32_t first = b->cfirst[k], n = b->cfirst[k + 1] - first;
		if (j->count)
			j->cnode[k] = 2 * (cluster_leaves(b->code, first, n) - 1);
		else {
			uint32_t next = j->cnode[k];
			build_cluster(b, &j->croot[k], first, n, &next);
		}
	}
	return NULL;
}

/* Run both jobs, the second on another thread when `par`. */
static void run_pair(struct cluster_job jobs[2], bool par)
{
	pthread_t th;
	bool threaded = par && pthread_create(&th, NULL, cluster_job_main, &jobs[1]) == 0;
	cluster_job_main(&jobs[0]);
	if (threaded)
		pthread_join(th, NULL);
	else
		cluster_job_main(&jobs[1]);
}

/* ---- the upper tree over clusters ---- */

static void build_top(const struct build *b, uint32_t ni, uint32_t first, uint32_t n, uint32_t next, int depth,
                      const struct fbox *cb);

struct top_job {
	const struct build *b;
	uint32_t ni, first, n, next;
	int depth;
	struct fbox cb;
};

static void *top_job_main(void *arg)
{
	struct top_job *j = arg;
	build_top(j->b, j->ni, j->first, j->n, j->next, j->depth, &j->cb);
	return NULL;
}

/* Node ni over clusters cref[first, first+n), whose doubled centroids lie
 * in *cb; its descendants take the 2n - 2 nodes from `next`. One pass bins
 * the clusters along the axis where their centroids spread most (each
 * bin keeping its box, its centroid box and its triangle count); the
 * cheapest boundary by the surface area heuristic is taken, a second pass
 * partitions, and the children's centroid boxes come from their bins. A
 * single cluster is its subtree's root. */
static void build_top(const struct build *b, uint32_t ni, uint32_t first, uint32_t n, uint32_t next, int depth,
                      const struct fbox *cb)
{
	struct mesh_node *nd = &b->nodes[ni];
	struct cref *r = b->cref + first;
	if (n == 1) {
		*nd = b->croot[cref_id(r)];
		return;
	}
	int axis = 0;
	for (int a = 1; a < 3; a++)
		if (cb->hi[a] - cb->lo[a] > cb->hi[axis] - cb->lo[axis])
			axis = a;
	float clo = cb->lo[axis], ext = cb->hi[axis] - clo;
	int nb = n < BINS ? (int)n : BINS;
	float scale = ext > 0 ? (float)nb / ext : 0;
	if (!isfinite(scale))
		scale = 0; /* centroids a few denormals apart: no bins */

	int split = 0;
	struct bin bins[BINS];
	if (scale > 0 && depth < DEPTH_MAX) {
		for (int k = 0; k < nb; k++) {
			fbox_empty(&bins[k].box);
			fbox_empty(&bins[k].cent);
			bins[k].n = 0;
		}
		for (uint32_t i = 0; i < n; i++) {
			struct bin *bn = &bins[bin_of(&r[i], axis, clo, scale, nb)];
			f4 lo = f4_load(r[i].f), hi = f4_load(r[i].f + 4), c = f4_add(f4_xyz(lo), f4_xyz(hi));
			f4_store(bn->box.lo, f4_min(f4_load(bn->box.lo), lo));
			f4_store(bn->box.hi, f4_max(f4_load(bn->box.hi), hi));
			f4_store(bn->cent.lo, f4_min(f4_load(bn->cent.lo), c));
			f4_store(bn->cent.hi, f4_max(f4_load(bn->cent.hi), c));
			bn->n += (uint32_t)r[i].f[7];
		}
		/* Right-hand sides of each boundary, then a sweep from the left. */
		float rarea[BINS];
		uint32_t rn[BINS];
		struct fbox acc;
		fbox_empty(&acc);
		uint32_t cnt = 0;
		for (int k = nb - 1; k >= 0; k--) {
			fbox_join(&acc, &bins[k].box);
			cnt += bins[k].n;
			rarea[k] = cnt ? half_area(&acc) : 0;
			rn[k] = cnt;
		}
		fbox_empty(&acc);
		cnt = 0;
		float best = INFINITY;
		for (int k = 0; k < nb - 1; k++) {
			fbox_join(&acc, &bins[k].box);
			cnt += bins[k].n;
			if (cnt == 0 || rn[k + 1] == 0)
				continue;
			float cost = half_area(&acc) * (float)cnt + rarea[k + 1] * (float)rn[k + 1];
			if (cost < best) {
				best = cost;
				split = k + 1;
			}
		}
	}
	struct fbox lc, rc;
	uint32_t mid = 0;
	if (split > 0) {
		/* Hoare's partition: swap only pairs that are both misplaced. */
		uint32_t i = 0, j = n;
		float fs = (float)split;
		for (;;) {
			while (i < j && bin_pos(&r[i], axis, clo, scale) < fs)
				i++;
			while (i < j && !(bin_pos(&r[j - 1], axis, clo, scale) < fs))
				j--;
			if (i >= j)
				break;
			struct cref t = r[i];
			r[i++] = r[--j];
			r[j] = t;
		}
		mid = i;
		fbox_empty(&lc);
		fbox_empty(&rc);
		for (int k = 0; k < nb; k++)
			fbox_join(k < split ? &lc : &rc, &bins[k].cent);
	}
	if (mid == 0 || mid == n) {
		/* All centroids equal, or too deep: halve the list. */
		mid = n / 2;
		cent_scan(&lc, r, mid);
		cent_scan(&rc, r + mid, n - mid);
	}
	uint32_t l = next, lnext = next + 2, rnext = lnext + 2 * mid - 2;
	nd->first = l;
	nd->count = 0;
	nd->axis = (uint16_t)axis;
	/* Large halves near the top: the left one on a thread of its own. */
	pthread_t th;
	bool threaded = false;
	struct top_job job = {b, l, first, mid, lnext, depth + 1, lc};
	if (n >= PAR_MIN && depth < PAR_DEPTH)
		threaded = pthread_create(&th, NULL, top_job_main, &job) == 0;
	if (!threaded)
		top_job_main(&job);
	build_top(b, l + 1, first + mid, n - mid, rnext, depth + 1, &rc);
	if (threaded)
		pthread_join(th, NULL);
	node_join(&b->nodes[ni], &b->nodes[l], &b->nodes[l + 1]);
}

/* The curve sort, in passes over the triangles that run on two threads
 * when there are many (run2): first half here, second half on the other. */
enum { DIGIT = 11, RADIX = 1 << DIGIT };

struct sorter {
	const struct mesh_data *d;
	uint32_t n;
	bool par;
	double lo[2][3], hi[2][3]; /* doubled centroids' bounds of each half */
	double clo[3], q, cells;   /* the grid */
	int idbits;
	uint64_t *src, *dst;       /* keys, and room for the next radix pass */
	int shift;                 /* the digit of this pass */
	uint32_t hist[2][RADIX];   /* its counts in each half, then where each half's keys go */
	struct idx3 *const *from[4]; /* per-face arrays to reorder (NULL: none) */
	struct idx3 *to[4];
};

static void run2(void (*fn)(struct sorter *, int, uint32_t, uint32_t), struct sorter *s);

struct run2_arg {
	void (*fn)(struct sorter *, int, uint32_t, uint32_t);
	struct sorter *s;
};

static void *run2_main(void *p)
{
	struct run2_arg *a = p;
	a->fn(a->s, 1, a->s->n / 2, a->s->n);
	return NULL;
}

static void run2(void (*fn)(struct sorter *, int, uint32_t, uint32_t), struct sorter *s)
{
	struct run2_arg a = {fn, s};
	pthread_t th;
	bool threaded = s->par && pthread_create(&th, NULL, run2_main, &a) == 0;
	fn(s, 0, 0, s->n / 2);
	if (threaded)
		pthread_join(th, NULL);
	else
		run2_main(&a);
}

/* A triangle's doubled centroid (of its box). */
static vec3 tri_centroid2(const struct mesh_data *d, uint32_t i)
{
	const struct idx3 *t = &d->tri[i];
	vec3 p = d->verts[t->i[0]], q = d->verts[t->i[1]], r = d->verts[t->i[2]];
	return v3_add(vmin(p, vmin(q, r)), vmax(p, vmax(q, r)));
}

static void sort_bounds(struct sorter *s, int part, uint32_t i0, uint32_t i1)
{
	vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3(-INFINITY, -INFINITY, -INFINITY);
	for (uint32_t i = i0; i < i1; i++) {
		vec3 c = tri_centroid2(s->d, i);
		lo = vmin(lo, c);
		hi = vmax(hi, c);
	}
	double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z};
	memcpy(s->lo[part], l, sizeof l);
	memcpy(s->hi[part], h, sizeof h);
}

static void sort_keys(struct sorter *s, int part, uint32_t i0, uint32_t i1)
{
	(void)part;
	for (uint32_t i = i0; i < i1; i++) {
		vec3 c = tri_centroid2(s->d, i);
		double cc[3] = {c.x, c.y, c.z};
		uint64_t g[3];
		for (int a = 0; a < 3; a++) {
			double x = (cc[a] - s->clo[a]) * s->q;
			g[a] = x > 0 ? x < s->cells ? (uint64_t)x : (uint64_t)s->cells : 0; /* NaN: 0 */
		}
		uint64_t m = spread3(g[0]) | spread3(g[1]) << 1 | spread3(g[2]) << 2;
		s->src[i] = m << s->idbits | i;
	}
}

static void sort_count(struct sorter *s, int part, uint32_t i0, uint32_t i1)
{
	uint32_t *h = s->hist[part];
	memset(h, 0, sizeof s->hist[part]);
	for (uint32_t i = i0; i < i1; i++)
		h[(s->src[i] >> s->shift) & (RADIX - 1)]++;
}

static void sort_scatter(struct sorter *s, int part, uint32_t i0, uint32_t i1)
{
	uint32_t *h = s->hist[part];
	for (uint32_t i = i0; i < i1; i++)
		s->dst[h[(s->src[i] >> s->shift) & (RADIX - 1)]++] = s->src[i];
}

static void sort_permute(struct sorter *s, int part, uint32_t i0, uint32_t i1)
{
	(void)part;
	uint64_t mask = ((uint64_t)1 << s->idbits) - 1;
	for (int a = 0; a < 4; a++)
		if (*s->from[a])
			for (uint32_t i = i0; i < i1; i++)
				s->to[a][i] = (*s->from[a])[s->src[i] & mask];
}

/* Sort d's triangles along the curve: reorder its per-face arrays and
 * return the sorted keys (n of them; the caller frees them). Each key is
 * a Morton code above the triangle's index: the index takes the low bits
 * it needs (*idbits), the code up to 21 bits per axis of the rest, on a
 * grid of cubic cells (so that a flat mesh is not cut into slivers).
 * Equal codes are ordered, and later split, by index. The sort is least
 * significant digit first, 11 bits at a time, skipping digits every key
 * shares; each pass counts then scatters both halves, the second half's
 * keys of each digit going after the first's, so the sort stays stable. */
static uint64_t *curve_sort(struct mesh_data *d, int *idbits)
{
	uint32_t n = d->ntris;
	struct sorter *s = calloc(1, sizeof *s);
	if (!s) abort();
	s->d = d;
	s->n = n;
	s->par = n >= PAR_MIN;
	run2(sort_bounds, s);
	double ext = 0;
	for (int a = 0; a < 3; a++) {
		s->clo[a] = fmin(s->lo[0][a], s->lo[1][a]);
		ext = fmax(ext, fmax(s->hi[0][a], s->hi[1][a]) - s->clo[a]);
	}
	s->idbits = 1;
	while (s->idbits < 32 && ((uint64_t)1 << s->idbits) < n)
		s->idbits++;
	int axbits = (64 - s->idbits) / 3 < 21 ? (64 - s->idbits) / 3 : 21;
	s->cells = (double)(((uint64_t)1 << axbits) - 1);
	s->q = ext > 0 && isfinite(ext) ? s->cells / ext : 0;
	s->src = malloc((size_t)n * sizeof *s->src);
	s->dst = malloc((size_t)n * sizeof *s->dst);
	if (!s->src || !s->dst) abort();
	run2(sort_keys, s);
	for (s->shift = s->idbits; s->shift < 64; s->shift += DIGIT) {
		run2(sort_count, s);
		uint32_t first = (uint32_t)(s->src[0] >> s->shift) & (RADIX - 1);
		if (s->hist[0][first] + s->hist[1][first] == n)
			continue; /* one digit for all: the order stays */
		uint32_t sum = 0;
		for (int k = 0; k < RADIX; k++) {
			uint32_t c0 = s->hist[0][k], c1 = s->hist[1][k];
			s->hist[0][k] = sum;
			s->hist[1][k] = sum + c0;
			sum += c0 + c1;
		}
		run2(sort_scatter, s);
		uint64_t *t = s->src;
		s->src = s->dst;
		s->dst = t;
	}
	free(s->dst);
	struct idx3 **arrs[4] = {&d->tri, &d->tri_n, &d->tri_uv, &d->tri_tex};
	for (int a = 0; a < 4; a++) {
		s->from[a] = arrs[a];
		s->to[a] = NULL;
		if (*arrs[a]) {
			s->to[a] = malloc((size_t)n * sizeof *s->to[a]);
			if (!s->to[a]) abort();
		}
	}
	run2(sort_permute, s);
	for (int a = 0; a < 4; a++)
		if (*arrs[a]) {
			free(*arrs[a]);
			*arrs[a] = s->to[a];
		}
	uint64_t *code = s->src;
	*idbits = s->idbits;
	free(s);
	return code;
}

static void build_hierarchy(struct mesh_data *d)
{
	uint32_t n = d->ntris;
	int idbits;
	uint64_t *code = curve_sort(d, &idbits);
	/* The low bits of a sorted code are the face's index before the sort
	 * (mesh_face reads faces in declaration order). */
	d->decl = malloc((size_t)n * sizeof *d->decl);
	if (!d->decl) abort();
	for (uint32_t j = 0; j < n; j++)
		d->decl[code[j] & (((uint64_t)1 << idbits) - 1)] = j;

	uint32_t *cfirst = malloc(((size_t)n + 1) * sizeof *cfirst);
	if (!cfirst) abort();
	uint32_t k = 0;
	make_clusters(code, 0, n, cfirst, &k);
	cfirst[k] = n;
	struct mesh_node *croot = malloc((size_t)k * sizeof *croot);
	struct cref *cref = malloc((size_t)k * sizeof *cref);
	uint32_t *cnode = malloc(((size_t)k + 1) * sizeof *cnode);
	if (!croot || !cref || !cnode) abort();
	struct build b = {.verts = d->verts, .tri = d->tri, .code = code, .cfirst = cfirst, .croot = croot,
	                  .cref = cref};

	/* The clusters' subtrees go below the upper tree's 2k - 1 nodes, each
	 * in a range of the size it needs, counted first; with many
	 * triangles, the second half of the clusters on another thread. */
	bool par = n >= PAR_MIN;
	struct cluster_job jobs[2] = {{&b, croot, cnode, 0, k / 2, true}, {&b, croot, cnode, k / 2, k, true}};
	run_pair(jobs, par);
	uint64_t total = 2 * (uint64_t)k - 1;
	for (uint32_t i = 0; i < k; i++) {
		uint32_t c = cnode[i];
		cnode[i] = (uint32_t)total;
		total += c;
	}
	b.nodes = malloc((size_t)total * sizeof *b.nodes);
	if (!b.nodes) abort();
	jobs[0].count = jobs[1].count = false;
	run_pair(jobs, par);
	free(cnode);

	for (uint32_t i = 0; i < k; i++) {
		float *f = cref[i].f;
		for (int a = 0; a < 3; a++) {
			f[a] = to_float(croot[i].box[0][a]);
			f[4 + a] = to_float(croot[i].box[1][a]);
		}
		memcpy(&f[3], &i, sizeof i);
		f[7] = (float)(cfirst[i + 1] - cfirst[i]);
	}
	struct fbox cb;
	cent_scan(&cb, cref, k);
	build_top(&b, 0, 0, k, 1, 0, &cb);
	free(cref);
	free(croot);
	free(cfirst);
	free(code);
	d->nodes = b.nodes;
	d->nnodes = (uint32_t)total;
}

static struct idx3 *copy_idx(const struct idx3 *a, uint32_t n)
{
	struct idx3 *c = malloc((size_t)(n ? n : 1) * sizeof *c);
	if (!c) abort();
	memcpy(c, a, (size_t)n * sizeof *c);
	return c;
}

/* Whether a face's three (unit) normals are one: POV-Ray then shades the
 * face flat, with its own normal, whatever direction the three give
 * (measured with trace(): a face whose normals are all <0, 0.6, -0.8>, or
 * <0, 0.6, -0.8> and <0, 1.2, -1.6>, reports the face normal <0, 0, -1>).
 * The second and third normals are compared with the first: within a
 * distance of 1e-5 they count as equal (measured: 1.00e-5 is flat, 1.02e-5
 * smooth, the same along an axis or a diagonal; <0,0,-1> with two normals
 * 0.9e-5 away on opposite sides, 1.8e-5 apart, is flat). */
static bool normals_equal(const vec3 *nrm, const struct idx3 *f)
{
	const double eps2 = 1e-10 * (1 + 1e-9); /* 1e-5 squared, and a last bit */
	vec3 a = nrm[f->i[0]];
	for (int k = 1; k < 3; k++) {
		vec3 e = v3_sub(nrm[f->i[k]], a);
		if (v3_dot(e, e) > eps2)
			return false;
	}
	return true;
}

/* Take the builder's arrays, apply mesh2's default indices, flatten the
 * faces whose normals are equal, drop degenerate faces, and build the
 * hierarchy. */
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

	if (d->tri_n)
		for (uint32_t i = 0; i < n; i++)
			if (d->tri_n[i].i[0] != MESH_NONE && normals_equal(d->normals, &d->tri_n[i]))
				d->tri_n[i] = no_idx;

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

size_t mesh_face_total(const struct object *o) { return data_of(o)->ntris; }

void mesh_face(const struct object *o, size_t i, struct mesh_face *f)
{
	const struct mesh_data *d = data_of(o);
	uint32_t k = d->decl[i];
	const struct idx3 *t = &d->tri[k];
	for (int c = 0; c < 3; c++)
		f->corner[c] = d->verts[t->i[c]];
	f->has_normals = d->tri_n && d->tri_n[k].i[0] != MESH_NONE;
	f->has_uv = d->tri_uv && d->tri_uv[k].i[0] != MESH_NONE;
	for (int c = 0; c < 3; c++) {
		f->normal[c] = f->has_normals ? d->normals[d->tri_n[k].i[c]] : v3(0, 0, 0);
		vec3 uv = f->has_uv ? d->uvs[d->tri_uv[k].i[c]] : v3(0, 0, 0);
		f->uv[c][0] = uv.x;
		f->uv[c][1] = uv.y;
	}
}

bool mesh_is(const struct object *o) { return o->ops == &mesh_ops; }

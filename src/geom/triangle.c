/* triangle.c: triangle { a, b, c } and smooth_triangle { a, na, b, nb, c, nc }.
 * Both are patches: POV-Ray gives them no inside. The hit's barycentrics
 * (h->u, h->v: the weights of b and c) carry the smooth normal. */
#include "geom/shapes.h"
#include "geom/tri.h"

#include <stdlib.h>

struct triangle {
	struct object base;
	vec3 p[3];
	vec3 n[3];       /* unit vertex normals (smooth triangles) */
	bool smooth;
	bool degenerate; /* never hit (zero area, or inconsistent normals) */
};

static bool triangle_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct triangle *tr = (const struct triangle *)o;
	struct tri_ray ray;
	struct tri_hit th;
	if (tr->degenerate || !tri_ray_init(&ray, r))
		return false;
	if (!tri_intersect(&ray, tr->p[0], tr->p[1], tr->p[2], tmin, tmax, &th))
		return false;
	h->t = th.t;
	h->part = 0;
	h->u = th.u;
	h->v = th.v;
	return true;
}

static int triangle_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	if (max < 1 || !triangle_intersect(o, r, tmin, tmax, out))
		return 0;
	out->obj = o;
	return 1;
}

static bool triangle_inside(const struct object *o, vec3 p)
{
	return false;
}

/* The flat normal (c - a) x (b - a), POV-Ray's orientation (its trace()
 * gives +y for <-1,0,-1>, <1,0,-1>, <0,0,1>); for a smooth triangle the unit vertex
 * normals interpolated linearly with the barycentrics, as POV-Ray does,
 * falling back to the flat one where they cancel. */
static vec3 triangle_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct triangle *tr = (const struct triangle *)o;
	vec3 flat = v3_cross(v3_sub(tr->p[2], tr->p[0]), v3_sub(tr->p[1], tr->p[0]));
	if (!tr->smooth)
		return flat;
	double u, v;
	if (h) {
		u = h->u;
		v = h->v;
	} else {
		tri_barycentric(tr->p[0], tr->p[1], tr->p[2], p, &u, &v);
	}
	vec3 n = v3_scale(tr->n[0], 1 - u - v);
	n = v3_madd(n, tr->n[1], u);
	n = v3_madd(n, tr->n[2], v);
	if (!(v3_dot(n, n) > 0) || !isfinite(v3_dot(n, n)))
		return flat;
	return n;
}

/* POV-Ray's box: that of the vertices carried by the object's transform
 * (not the object-space box moved: triangle { 0, x, y rotate <20,30,40> }
 * reaches y = 0.829769, not the 1.386440 of its box rotated), widened by
 * 1e-10 each way (min_extent of triangle { 0, x, y } is -1e-10, which
 * prints as -0.000000). */
static struct aabb vertex_box(const struct triangle *tr, const mat4 *m)
{
	struct aabb b = aabb_empty();
	for (int i = 0; i < 3; i++)
		b = aabb_add_point(b, m ? mat_point(m, tr->p[i]) : tr->p[i]);
	vec3 e = v3(1e-10, 1e-10, 1e-10);
	return (struct aabb){v3_sub(b.lo, e), v3_add(b.hi, e)};
}

static struct aabb triangle_bounds(const struct object *o)
{
	return vertex_box((const struct triangle *)o, NULL);
}

static struct aabb triangle_world_bounds(const struct object *o)
{
	return vertex_box((const struct triangle *)o, o->has_xf ? &o->xf.fwd : NULL);
}

static struct object *triangle_copy(const struct object *o)
{
	struct triangle *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct triangle *)o;
	return &c->base;
}

static const struct object_ops triangle_ops = {
	.name = "triangle",
	.intersect = triangle_intersect,
	.all_hits = triangle_all_hits,
	.inside = triangle_inside,
	.normal = triangle_normal,
	.bounds = triangle_bounds,
	.world_bounds = triangle_world_bounds,
	.copy = triangle_copy,
};

static const struct object_ops smooth_triangle_ops = {
	.name = "smooth_triangle",
	.intersect = triangle_intersect,
	.all_hits = triangle_all_hits,
	.inside = triangle_inside,
	.normal = triangle_normal,
	.bounds = triangle_bounds,
	.world_bounds = triangle_world_bounds,
	.copy = triangle_copy,
};

static struct triangle *make(const struct object_ops *ops, vec3 a, vec3 b, vec3 c, struct srcpos pos)
{
	struct triangle *t = calloc(1, sizeof *t);
	if (!t) abort();
	object_init(&t->base, ops, pos);
	t->p[0] = a;
	t->p[1] = b;
	t->p[2] = c;
	t->degenerate = tri_degenerate(a, b, c);
	return t;
}

struct object *triangle_new(vec3 a, vec3 b, vec3 c, struct srcpos pos)
{
	return &make(&triangle_ops, a, b, c, pos)->base;
}

/* POV-Ray normalises the vertex normals, and drops a stand-alone smooth
 * triangle whose normals do not all point to one side of its plane. */
struct object *smooth_triangle_new(vec3 a, vec3 na, vec3 b, vec3 nb, vec3 c, vec3 nc, struct srcpos pos)
{
	struct triangle *t = make(&smooth_triangle_ops, a, b, c, pos);
	t->smooth = true;
	t->n[0] = v3_norm(na);
	t->n[1] = v3_norm(nb);
	t->n[2] = v3_norm(nc);
	t->degenerate = tri_smooth_degenerate(a, t->n[0], b, t->n[1], c, t->n[2]);
	return &t->base;
}

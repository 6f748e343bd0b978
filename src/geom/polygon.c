/* polygon.c: polygon { n, points }: flat sub-polygons in one plane, with a
 * hole wherever an even number of them overlap (the even-odd rule). The
 * points are kept as 2-D coordinates in the plane (along two unit axes u
 * and v from the first point); the normal is (P1 - P0) x (P2 - P0) of the
 * first three points not on one line, which is what POV-Ray's trace()
 * returns whichever side the ray comes from. A polygon is a patch: it has
 * no inside. */
#include "geom/shapes2.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

struct polygon {
	struct object base;
	double (*edge)[4];   /* edges (u0, v0, u1, v1) */
	int nedge;
	vec3 org, ax_u, ax_v, n; /* the plane: a point, two unit axes, the normal (unit) */
	double lo[2], hi[2]; /* extent of the points in u and v */
	vec3 *pts;           /* the points as given, for the bounds */
	int npts;
};

/* Even-odd rule: the crossings of the half-line from (u, v) towards +u;
 * an edge counts when one end is above v and the other not (so a vertex
 * on the half-line counts once for the edges that cross it). */
static bool inside_2d(const struct polygon *P, double u, double v)
{
	if (!(u >= P->lo[0] && u <= P->hi[0] && v >= P->lo[1] && v <= P->hi[1]))
		return false;
	bool in = false;
	for (int i = 0; i < P->nedge; i++) {
		const double *e = P->edge[i];
		if ((e[1] > v) == (e[3] > v))
			continue;
		double x = e[0] + (v - e[1]) * (e[2] - e[0]) / (e[3] - e[1]);
		if (x > u)
			in = !in;
	}
	return in;
}

static bool polygon_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	const struct polygon *P = (const struct polygon *)o;
	double dn = v3_dot(r->dir, P->n);
	if (dn == 0)
		return false;
	double t = v3_dot(v3_sub(P->org, r->org), P->n) / dn;
	if (!(t > tmin && t < tmax))
		return false;
	vec3 q = v3_sub(v3_madd(r->org, r->dir, t), P->org);
	if (!inside_2d(P, v3_dot(q, P->ax_u), v3_dot(q, P->ax_v)))
		return false;
	h->t = t;
	h->part = 0;
	return true;
}

static int polygon_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                            int max)
{
	if (max < 1 || !polygon_intersect(o, r, tmin, tmax, out))
		return 0;
	out->obj = o;
	return 1;
}

static bool polygon_inside(const struct object *o, vec3 p)
{
	(void)o;
	(void)p;
	return false;
}

static vec3 polygon_normal(const struct object *o, vec3 p, const struct hit *h)
{
	(void)p;
	(void)h;
	return ((const struct polygon *)o)->n;
}

/* POV-Ray's box: that of the points carried by the object's transform
 * (polygon { 3, <0,0>, <1,0>, <0,1> rotate <20,30,40> } reaches y =
 * 0.829769, not the 1.386440 of its box rotated), with every side shorter
 * than 0.001 widened by 0.001 each way (measured: a side 0.00099 long is
 * widened, one 0.001 long is not; a polygon in the plane z = 0 scaled by
 * 10 is still 0.002 thick). */
static struct aabb point_box(const struct polygon *P, const mat4 *m)
{
	struct aabb b = aabb_empty();
	for (int i = 0; i < P->npts; i++)
		b = aabb_add_point(b, m ? mat_point(m, P->pts[i]) : P->pts[i]);
	for (int k = 0; k < 3; k++) {
		double *l = k == 0 ? &b.lo.x : k == 1 ? &b.lo.y : &b.lo.z;
		double *h = k == 0 ? &b.hi.x : k == 1 ? &b.hi.y : &b.hi.z;
		if (*h - *l < 0.001) {
			*l -= 0.001;
			*h += 0.001;
		}
	}
	return b;
}

static struct aabb polygon_bounds(const struct object *o)
{
	return point_box((const struct polygon *)o, NULL);
}

static struct aabb polygon_world_bounds(const struct object *o)
{
	return point_box((const struct polygon *)o, o->has_xf ? &o->xf.fwd : NULL);
}

static struct object *polygon_copy(const struct object *o)
{
	const struct polygon *P = (const struct polygon *)o;
	struct polygon *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *P;
	c->edge = malloc((size_t)(P->nedge ? P->nedge : 1) * sizeof *c->edge);
	if (!c->edge) abort();
	if (P->nedge)
		memcpy(c->edge, P->edge, (size_t)P->nedge * sizeof *c->edge);
	c->pts = malloc((size_t)(P->npts ? P->npts : 1) * sizeof *c->pts);
	if (!c->pts) abort();
	if (P->npts)
		memcpy(c->pts, P->pts, (size_t)P->npts * sizeof *c->pts);
	return &c->base;
}

static void polygon_destroy(struct object *o)
{
	free(((struct polygon *)o)->edge);
	free(((struct polygon *)o)->pts);
}

static const struct object_ops polygon_ops = {
	.name = "polygon",
	.intersect = polygon_intersect,
	.all_hits = polygon_all_hits,
	.inside = polygon_inside,
	.normal = polygon_normal,
	.bounds = polygon_bounds,
	.world_bounds = polygon_world_bounds,
	.copy = polygon_copy,
	.destroy = polygon_destroy,
};

static bool same_point(vec3 a, vec3 b)
{
	return a.x == b.x && a.y == b.y && a.z == b.z;
}

static void add_edge(struct polygon *P, const double *a, const double *b)
{
	double *e = P->edge[P->nedge++];
	e[0] = a[0];
	e[1] = a[1];
	e[2] = b[0];
	e[3] = b[1];
}

struct object *polygon_new(const vec3 *pts, int n, struct srcpos pos, bool *closed_last, bool *nonplanar)
{
	if (nonplanar)
		*nonplanar = false;
	if (closed_last)
		*closed_last = false;
	/* The plane: the first three points not on one line. */
	vec3 nrm = v3(0, 0, 0);
	for (int i = 1; i + 1 < n && !(v3_dot(nrm, nrm) > 0); i++)
		for (int j = i + 1; j < n && !(v3_dot(nrm, nrm) > 0); j++)
			nrm = v3_cross(v3_sub(pts[i], pts[0]), v3_sub(pts[j], pts[0]));
	bool collinear = !(v3_dot(nrm, nrm) > 0) || !isfinite(v3_dot(nrm, nrm)), flat = collinear;
	if (flat)
		nrm = v3(0, 0, 1); /* on one line: never hit, as in POV-Ray */
	struct polygon *P = calloc(1, sizeof *P);
	if (!P) abort();
	object_init(&P->base, &polygon_ops, pos);
	P->n = v3_norm(nrm);
	P->org = pts[0];
	/* Points off the plane: POV-Ray then never shows the polygon, with no
	 * message (measured: a unit square with a corner moved 1e-9 off its
	 * plane is never hit, 1e-10 is; for a square ten times the size the
	 * limits are ten times smaller). */
	double scale = sqrt(v3_len(nrm));
	for (int i = 0; i < n && !flat; i++)
		if (fabs(v3_dot(v3_sub(pts[i], pts[0]), P->n)) * scale > 5e-10)
			flat = true;
	if (flat)
		P->n = v3(0, 0, 1);
	if (nonplanar)
		*nonplanar = flat && !collinear;
	/* u along the first edge that has a length, v = n x u. */
	vec3 u = v3(0, 0, 0);
	for (int i = 1; i < n && !(v3_dot(u, u) > 0); i++)
		u = v3_sub(pts[i], pts[0]);
	u = v3_sub(u, v3_scale(P->n, v3_dot(u, P->n)));
	P->ax_u = flat ? v3(1, 0, 0) : v3_norm(u);
	P->ax_v = v3_cross(P->n, P->ax_u);

	P->edge = malloc((size_t)(n + 1) * sizeof *P->edge);
	if (!P->edge) abort();
	P->lo[0] = P->lo[1] = INFINITY;
	P->hi[0] = P->hi[1] = -INFINITY;
	double (*uv)[2] = malloc((size_t)n * sizeof *uv);
	if (!uv) abort();
	for (int i = 0; i < n; i++) {
		vec3 q = v3_sub(pts[i], P->org);
		uv[i][0] = v3_dot(q, P->ax_u);
		uv[i][1] = v3_dot(q, P->ax_v);
		for (int k = 0; k < 2; k++) {
			P->lo[k] = fmin(P->lo[k], uv[i][k]);
			P->hi[k] = fmax(P->hi[k], uv[i][k]);
		}
	}
	/* Sub-polygons: from a first point to the next point equal to it;
	 * the last one, if it never comes back, is closed. */
	int i = 0;
	while (!flat && i < n) {
		int s = i, j = i + 1;
		while (j < n && !same_point(pts[j], pts[s]))
			j++;
		bool closed = j < n;
		int last = closed ? j : n - 1; /* edges k -> k + 1 for k < last */
		for (int k = s; k < last; k++)
			add_edge(P, uv[k], uv[k + 1]);
		if (!closed) {
			if (last > s) {
				if (closed_last)
					*closed_last = true;
				add_edge(P, uv[last], uv[s]);
			}
			break;
		}
		i = j + 1;
	}
	free(uv);
	P->npts = n;
	P->pts = malloc((size_t)(n ? n : 1) * sizeof *P->pts);
	if (!P->pts) abort();
	if (n)
		memcpy(P->pts, pts, (size_t)n * sizeof *P->pts);
	return &P->base;
}

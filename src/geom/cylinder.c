/* cylinder.c: cone { base, r0, cap, r1 [open] } and cylinder { base, cap,
 * radius [open] }, one primitive: a cylinder is a cone with equal radii.
 *
 * The work happens in a frame (u, v, w) with its origin at the base point
 * and w pointing to the cap, where the side is x^2 + y^2 = rho(z)^2 with
 * rho(z) = r0 + k z, 0 <= z <= len, and the end caps are discs in the planes
 * z = 0 and z = len. Only rho^2 matters, so a cone whose radii have opposite
 * signs is two cones meeting at a point (POV-Ray's inside() agrees; its
 * renders clip that shape to a box of radius max(r0, r1)), and negating both
 * radii changes nothing (POV-Ray then behaves erratically). As in POV-Ray,
 * an open cone has no caps but its inside is still that of the closed
 * solid. */
#include "geom/shapes.h"
#include "geom/frame.h"

#include <stdlib.h>

enum { PART_SIDE, PART_BASE, PART_CAP };

struct cone {
	struct object base;
	vec3 org;      /* the base point */
	vec3 u, v, w;  /* orthonormal frame; w points from base to cap */
	double len;    /* distance from base to cap */
	double r0, r1; /* radii at base and cap as given (signed) */
	double k;      /* (r1 - r0) / len: the change of rho along w */
	bool open;     /* no end caps */
	bool empty;    /* len == 0 or both radii 0: nothing to hit */
};

/* The ray in the cone's frame: a rotation and a translation, so t is kept. */
static void to_frame(const struct cone *c, const struct ray *r, vec3 *o, vec3 *d)
{
	vec3 p = v3_sub(r->org, c->org);
	*o = v3(v3_dot(p, c->u), v3_dot(p, c->v), v3_dot(p, c->w));
	*d = v3(v3_dot(r->dir, c->u), v3_dot(r->dir, c->v), v3_dot(r->dir, c->w));
}

static void add(double *t, int *part, int *n, double tt, int pp)
{
	if (!isfinite(tt))
		return;
	int i = *n;
	while (i > 0 && t[i - 1] > tt) {
		t[i] = t[i - 1];
		part[i] = part[i - 1];
		i--;
	}
	t[i] = tt;
	part[i] = pp;
	(*n)++;
}

/* a^2 + b^2 - c^2. When the difference nearly cancels (rays grazing the
 * side) the rounding errors of the squares are recovered with fma and the
 * sum's with a two-sum, so the result keeps the precision of a, b and c. */
static double sq_diff(double a, double b, double c)
{
	double a2 = a * a, b2 = b * b, c2 = c * c, s = a2 + b2;
	double d = s - c2;
	if (fabs(d) >= 0.5 * c2)
		return d;
	double es = fabs(a2) >= fabs(b2) ? (a2 - s) + b2 : (b2 - s) + a2;
	return d + es + (fma(a, a, -a2) + fma(b, b, -b2) - fma(c, c, -c2));
}

/* Every crossing of the ray with the surface, in increasing t (at most 4);
 * t is not limited to any range here. The side's quadratic is
 * a t^2 + 2 hb t + c with the discriminant formed as
 * |rho_o D - rho_d P|^2 - (P x D)^2 (P, D: the ray's origin and direction
 * across the axis), which equals hb^2 - a c but does not cancel for rays
 * far from the axis or nearly tangent; the near root comes from q so that
 * nothing cancels there either. A ray in the surface (a = hb = 0) crosses
 * nothing; a ray parallel to a generator has one root. Side points at the
 * rims (z = 0 or len) and cap points on the rim (rho^2) both count, so a
 * ray through an edge cannot slip between the two. */
static int crossings(const struct cone *c, const struct ray *r, double t[4], int part[4])
{
	int n = 0;
	if (c->empty)
		return 0;
	vec3 o, d;
	to_frame(c, r, &o, &d);
	double rho_o = c->r0 + c->k * o.z, rho_d = c->k * d.z;
	double a = d.x * d.x + d.y * d.y - rho_d * rho_d;
	double hb = o.x * d.x + o.y * d.y - rho_o * rho_d;
	double cc = o.x * o.x + o.y * o.y - rho_o * rho_o;
	double ts[2];
	int ns = 0;
	if (a == 0) {
		if (hb != 0)
			ts[ns++] = -cc / (2 * hb);
	} else {
		double ex = rho_o * d.x - rho_d * o.x, ey = rho_o * d.y - rho_d * o.y;
		double cr = o.x * d.y - o.y * d.x;
		double disc = sq_diff(ex, ey, cr);
		if (disc >= 0) {
			double q = -(hb + copysign(sqrt(disc), hb));
			if (q == 0) {
				ts[ns++] = 0; /* hb = disc = 0, so c = 0: touching at the origin */
			} else {
				ts[ns++] = q / a;
				ts[ns++] = cc / q;
			}
		}
	}
	for (int i = 0; i < ns; i++) {
		double z = o.z + ts[i] * d.z;
		if (z >= 0 && z <= c->len)
			add(t, part, &n, ts[i], PART_SIDE);
	}
	if (!c->open && d.z != 0) {
		for (int e = 0; e < 2; e++) {
			double zc = e ? c->len : 0, rc = e ? c->r1 : c->r0;
			double tc = (zc - o.z) / d.z;
			double x = o.x + tc * d.x, y = o.y + tc * d.y;
			if (x * x + y * y <= rc * rc)
				add(t, part, &n, tc, e ? PART_CAP : PART_BASE);
		}
	}
	return n;
}

static bool cone_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	double t[4];
	int part[4];
	int n = crossings((const struct cone *)o, r, t, part);
	for (int i = 0; i < n; i++)
		if (t[i] > tmin && t[i] < tmax) {
			h->t = t[i];
			h->part = part[i];
			return true;
		}
	return false;
}

static int cone_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max)
{
	double t[4];
	int part[4], k = 0;
	int n = crossings((const struct cone *)o, r, t, part);
	for (int i = 0; i < n && k < max; i++)
		if (t[i] > tmin && t[i] < tmax) {
			out[k].t = t[i];
			out[k].part = part[i];
			out[k].obj = o;
			k++;
		}
	return k;
}

/* Strictly inside the closed solid, whether or not the cone is open. */
static bool cone_inside(const struct object *o, vec3 p)
{
	const struct cone *c = (const struct cone *)o;
	if (c->empty)
		return false;
	vec3 q = v3_sub(p, c->org);
	double z = v3_dot(q, c->w);
	if (!(z > 0 && z < c->len))
		return false;
	double x = v3_dot(q, c->u), y = v3_dot(q, c->v), rho = c->r0 + c->k * z;
	return x * x + y * y < rho * rho;
}

/* The side's gradient (x, y, -rho k) in the frame. At the apex it
 * vanishes; there the axis away from the body stands in for it. */
static vec3 side_normal(const struct cone *c, double x, double y, double z)
{
	double rho = c->r0 + c->k * z;
	vec3 n = v3_add(v3_add(v3_scale(c->u, x), v3_scale(c->v, y)), v3_scale(c->w, -rho * c->k));
	if (v3_dot(n, n) > 0)
		return n;
	return v3_scale(c->w, z < 0.5 * c->len ? -1 : 1);
}

static vec3 cone_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct cone *c = (const struct cone *)o;
	vec3 q = v3_sub(p, c->org);
	double x = v3_dot(q, c->u), y = v3_dot(q, c->v), z = v3_dot(q, c->w);
	int part = h ? h->part : -1;
	if (part < PART_SIDE || part > PART_CAP || (c->open && part != PART_SIDE)) {
		/* No usable hit record: the surface nearest to p. */
		double rho = c->r0 + c->k * z;
		double ds = fabs(sqrt(x * x + y * y) - fabs(rho)) / sqrt(1 + c->k * c->k);
		part = PART_SIDE;
		if (!c->open && fabs(z) < ds)
			part = PART_BASE, ds = fabs(z);
		if (!c->open && fabs(z - c->len) < ds)
			part = PART_CAP;
	}
	if (part == PART_BASE)
		return v3_neg(c->w);
	if (part == PART_CAP)
		return c->w;
	return side_normal(c, x, y, z);
}

/* The box around the two end discs: a disc of radius r around the unit
 * axis w reaches r sqrt(1 - w_i^2) along axis i. */
static const struct object_ops cone_ops;

/* POV-Ray's box, measured with min_extent/max_extent (cylinder { 0,
 * <1,2.5,1>, 1 } gives x in [-1.278929, 2.278929], where the exact box
 * has [-0.937, 1.937]): the box of the corners of [-R,R]^2 x [0,len], R
 * the larger radius, carried to the axis by the rotation that takes z to
 * minus the axis w (about z x -w; the identity for w = z), which gives
 * x' = (1 - wx^2/(1-wz), -wx wy/(1-wz), wx) and
 * y' = (-wx wy/(1-wz), 1 - wy^2/(1-wz), wy), and then by the object's
 * transform as one matrix (not the box moved: cylinder { <1,0.5,0>,
 * <2,3,1>, 0.5 rotate <20,30,40> } gives x in [-0.190467, 1.104903]).
 * This is that whole map, from [-1,1]^2 x [0,1]. POV-Ray builds the
 * rotation with sines and cosines, so a side that should be 0 can be
 * -6e-17 there (cylinder { y, 0, 1 }: min_extent's y prints -0.000000);
 * lucent's is exact. A cone's axis runs from the end with the larger
 * radius to the other, and R is that radius, signs counted (cone { <1,
 * 0.5,0>, 0.5, <0,1,1>, 1.5 }: x in [-1.3, 2.3], where w from base to cap
 * would give [-1.5, 2.5]; cone { 0, -1, x+y, 0.5 }: x in [-0.5, 1.5]). */
static mat4 canonical_frame(const struct cone *c)
{
	vec3 w = c->w, org = c->org;
	if (c->base.ops == &cone_ops && c->r0 < c->r1) {
		org = v3_madd(c->org, w, c->len);
		w = v3_neg(w);
	}
	double r = fmax(c->r0, c->r1);
	return geom_axis_frame(w, r, r, c->len, org);
}

static const struct aabb canonical_box = {{-1, -1, 0}, {1, 1, 1}};

static struct aabb cone_bounds(const struct object *o)
{
	const struct cone *c = (const struct cone *)o;
	if (c->len == 0)
		return (struct aabb){c->org, c->org};
	mat4 f = canonical_frame(c);
	return mat_bounds(&f, canonical_box);
}

static struct aabb cone_world_bounds(const struct object *o)
{
	const struct cone *c = (const struct cone *)o;
	if (!o->has_xf || c->len == 0)
		return o->has_xf ? mat_bounds(&o->xf.fwd, cone_bounds(o)) : cone_bounds(o);
	mat4 f = canonical_frame(c), m = mat_mul(&o->xf.fwd, &f);
	return mat_bounds(&m, canonical_box);
}

static struct object *cone_copy(const struct object *o)
{
	struct cone *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *(const struct cone *)o;
	return &c->base;
}

static const struct object_ops cone_ops = {
	.name = "cone",
	.intersect = cone_intersect,
	.all_hits = cone_all_hits,
	.inside = cone_inside,
	.normal = cone_normal,
	.bounds = cone_bounds,
	.world_bounds = cone_world_bounds,
	.copy = cone_copy,
};

static const struct object_ops cylinder_ops = {
	.name = "cylinder",
	.intersect = cone_intersect,
	.all_hits = cone_all_hits,
	.inside = cone_inside,
	.normal = cone_normal,
	.bounds = cone_bounds,
	.world_bounds = cone_world_bounds,
	.copy = cone_copy,
};

static struct object *make(const struct object_ops *ops, vec3 base, double r0, vec3 cap, double r1, bool open,
                           struct srcpos pos)
{
	struct cone *c = calloc(1, sizeof *c);
	if (!c) abort();
	object_init(&c->base, ops, pos);
	vec3 axis = v3_sub(cap, base);
	c->org = base;
	c->len = v3_len(axis);
	c->r0 = r0;
	c->r1 = r1;
	c->open = open;
	if (!(c->len > 0 && isfinite(c->len))) {
		/* base == cap (POV-Ray's parser rejects it): keep a valid frame so
		 * that nothing downstream divides by zero. */
		c->len = 0;
		c->w = v3(0, 1, 0);
	} else {
		c->w = v3_scale(axis, 1 / c->len);
		c->k = (r1 - r0) / c->len;
	}
	c->empty = c->len == 0 || (r0 == 0 && r1 == 0);
	/* u: the cross product with the coordinate axis least aligned with w. */
	vec3 ax = fabs(c->w.x) <= fabs(c->w.y) && fabs(c->w.x) <= fabs(c->w.z) ? v3(1, 0, 0)
	          : fabs(c->w.y) <= fabs(c->w.z)                               ? v3(0, 1, 0)
	                                                                       : v3(0, 0, 1);
	c->u = v3_norm(v3_cross(c->w, ax));
	c->v = v3_cross(c->w, c->u);
	return &c->base;
}

struct object *cone_new(vec3 base, double r0, vec3 cap, double r1, bool open, struct srcpos pos)
{
	return make(&cone_ops, base, r0, cap, r1, open, pos);
}

struct object *cylinder_new(vec3 base, vec3 cap, double radius, bool open, struct srcpos pos)
{
	return make(&cylinder_ops, base, radius, cap, radius, open, pos);
}

/* warp.c: carrying a point into pattern space through the pattern's
 * transformations and warps (see pattern.h). Every formula here was
 * measured against POV-Ray 3.7 (`function { pattern { function { x } warp
 * {...} } }`); doc/materials-noise.md describes each warp. */
#include "pattern/pattern.h"

#include <math.h>

/* The kinds whose classic `turbulence` POV-Ray folds into the value rather
 * than applying to the point (see noisy.c). */
static bool turbulence_in_value(enum pattern_kind k)
{
	return k == PAT_MARBLE || k == PAT_WOOD || k == PAT_SPIRAL1 ||
	       k == PAT_SPIRAL2;
}

/* warp { repeat }: fold the repeat axis into [0, width), mirror odd copies
 * along the flip axes, and shift the n-th copy by n × offset. */
static vec3 warp_repeat(const struct pattern_op *op, vec3 p)
{
	int axis = op->v1.x != 0 ? 0 : op->v1.y != 0 ? 1 : 2;
	double w = v3_get(op->v1, axis);
	if (w == 0)
		return p;
	double c[3] = {p.x, p.y, p.z};
	double n = floor(c[axis] / w);
	c[axis] -= n * w;
	if (fmod(n, 2.0) != 0) {        /* an odd copy: mirrored along the flip axes */
		double flip[3] = {op->v3.x, op->v3.y, op->v3.z};
		for (int i = 0; i < 3; i++) {
			if (flip[i] == 0)
				continue;
			c[i] = i == axis ? w - c[i] : -c[i];
		}
	}
	return v3_add(v3(c[0], c[1], c[2]), v3_scale(op->v2, n));
}

/* A black hole's centre for the block p lies in, with repeat; the random
 * offset per block (turbulence) comes from the vector noise at the block's
 * index, in [0, 1) per axis. */
static vec3 black_hole_centre(const struct pattern_op *op, vec3 p, int generator)
{
	vec3 rep = op->v2;
	if (rep.x == 0 && rep.y == 0 && rep.z == 0)
		return op->v1;
	vec3 block = v3(rep.x != 0 ? floor(p.x / rep.x) : 0, rep.y != 0 ? floor(p.y / rep.y) : 0,
	                rep.z != 0 ? floor(p.z / rep.z) : 0);
	vec3 c = v3_add(op->v1, v3_mul(block, rep));
	if (op->v3.x != 0 || op->v3.y != 0 || op->v3.z != 0) {
		vec3 r = dnoise3(v3_add(block, v3(0.5, 0.5, 0.5)), generator);
		vec3 u = v3(r.x - floor(r.x), r.y - floor(r.y), r.z - floor(r.z));
		c = v3_add(c, v3_mul(op->v3, u));
	}
	return c;
}

/* warp { black_hole C, R }: a point at distance r < R from the centre moves
 * along the radius by the factor 1 ± min(1, strength × (1 − r/R)^falloff):
 * outward normally, inward with `inverse`. */
static vec3 warp_black_hole(const struct pattern_op *op, vec3 p, int generator)
{
	double radius = op->f1;
	vec3 c = black_hole_centre(op, p, generator);
	vec3 d = v3_sub(p, c);
	double r = v3_len(d);
	if (radius <= 0 || r >= radius || r == 0)
		return p;
	double force = op->f3 * pow(1.0 - r / radius, op->f2);
	if (force > 1)
		force = 1;
	double k = op->f4 != 0 ? 1.0 - force : 1.0 + force;
	return v3_madd(c, d, k);
}

/* The mapping warps compute (u, v, distance) about the y axis, then turn
 * the result by POV-Ray's orientation matrix for o = (a, b, c), which is
 * [[c+b, 0, a], [0, c+a, −b], [−a, b, c]] (not a rotation unless o is an
 * axis; measured). */
static vec3 orient(vec3 o, vec3 q)
{
	o = v3_norm(o);
	if (o.x == 0 && o.y == 0 && o.z == 0)
		o = v3(0, 0, 1);
	return v3((o.z + o.y) * q.x + o.x * q.z, (o.z + o.x) * q.y - o.y * q.z,
	          -o.x * q.x + o.y * q.y + o.z * q.z);
}

static double turn(double z, double x)
{
	double u = atan2(z, x) / (2 * M_PI);
	return u < 0 ? u + 1 : u;
}

static vec3 warp_mapping(const struct pattern_op *op, vec3 p)
{
	double rho = sqrt(p.x * p.x + p.z * p.z);
	double u = turn(p.z, p.x), v, d;
	switch (op->kind) {
	case POP_CYLINDRICAL:
		d = rho;
		v = p.y;
		if (op->f1 != 0)
			u *= pow(d, op->f1);
		return orient(op->v1, v3(u, v, d));
	case POP_SPHERICAL:
		d = v3_len(p);
		v = d > 0 ? asin(fmax(-1.0, fmin(1.0, p.y / d))) / M_PI + 0.5 : 0.5;
		break;
	default: {                      /* POP_TOROIDAL: f2 is the major radius */
		double dr = rho - op->f2;
		d = sqrt(dr * dr + p.y * p.y);
		v = atan2(p.y, dr) / (2 * M_PI) + 0.5;
		break;
	}
	}
	if (op->f1 != 0) {
		double s = pow(d, op->f1);
		u *= s;
		v *= s;
	}
	return orient(op->v1, v3(u, v, d));
}

/* warp { cubic }: the point's direction laid out as a box's uv mapping
 * lays out the faces of the cube [-1,1]^3 (4 x 3 cells in the unit
 * square), with its max-norm distance from the origin as the third
 * coordinate. Measured against POV-Ray 3.7 with gradient patterns, ties
 * between faces included. */
static vec3 warp_cubic(vec3 p)
{
	/* Per face (2*axis + positive side): cell column and row, the axes
	 * u and v follow, and whether each runs reversed (as box.c's uv). */
	static const struct { int col, row, ua, va; bool uflip, vflip; } cell[6] = {
		{0, 1, 2, 1, false, false}, {2, 1, 2, 1, true, false},
		{1, 0, 0, 2, false, false}, {1, 2, 0, 2, false, true},
		{3, 1, 0, 1, true, false},  {1, 1, 0, 1, false, false},
	};
	double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
	double d = fmax(ax, fmax(ay, az));
	if (!(d > 0))
		return v3(0, 0, 0);
	int axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
	int face = 2 * axis + (v3_get(p, axis) > 0);
	double c[2];
	int a[2] = {cell[face].ua, cell[face].va};
	bool flip[2] = {cell[face].uflip, cell[face].vflip};
	for (int i = 0; i < 2; i++) {
		double t = (v3_get(p, a[i]) / d + 1) / 2;
		c[i] = flip[i] ? 1 - t : t;
	}
	return v3((cell[face].col + c[0]) / 4, (cell[face].row + c[1]) / 3, d);
}

static vec3 apply_op(const struct pattern_op *op, vec3 p, int generator)
{
	switch (op->kind) {
	case POP_TRANSFORM:
		return mat_point(&op->xf.inv, p);
	case POP_TURBULENCE:
		return v3_add(p, v3_mul(op->turb.amount, turbulence3(p, &op->turb, generator)));
	case POP_REPEAT:
		return warp_repeat(op, p);
	case POP_BLACK_HOLE:
		return warp_black_hole(op, p, generator);
	case POP_CYLINDRICAL: case POP_SPHERICAL: case POP_TOROIDAL:
		return warp_mapping(op, p);
	case POP_PLANAR:
		return orient(op->v1, v3(p.x, p.y, op->f1));
	case POP_CUBIC:
		return warp_cubic(p);
	}
	return p;
}

static vec3 carry(const struct pattern *pt, vec3 p, int generator)
{
	if (pt->noise_generator)
		generator = pt->noise_generator;
	for (int i = pt->nops - 1; i >= 0; i--)
		p = apply_op(&pt->ops[i], p, generator);
	if (pt->has_turbulence && !turbulence_in_value(pt->kind))
		p = v3_add(p, v3_mul(pt->turb.amount, turbulence3(p, &pt->turb, generator)));
	return p;
}

vec3 pattern_point(const struct pattern *pt, vec3 p)
{
	return carry(pt, p, 2);
}

vec3 pattern_point_ctx(const struct pattern *pt, vec3 p, const struct pattern_ctx *ctx)
{
	return carry(pt, p, ctx && ctx->noise_generator ? ctx->noise_generator : 2);
}

double pattern_value_moved(const struct pattern *pt, vec3 p, vec3 off, const struct pattern_ctx *ctx)
{
	int generator = pt->noise_generator ? pt->noise_generator
	              : ctx && ctx->noise_generator ? ctx->noise_generator : 2;
	for (int i = pt->nops - 1; i >= 0; i--)
		p = apply_op(&pt->ops[i], p, generator);
	if (pt->has_turbulence && !turbulence_in_value(pt->kind))
		p = v3_add(p, v3_mul(pt->turb.amount, turbulence3(p, &pt->turb, generator)));
	p = v3_add(p, off);
	double v = pattern_raw(pt, p, ctx);
	return pattern_is_block(pt->kind) ? v : pattern_wave(pt, v);
}

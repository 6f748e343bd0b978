/* geometric.c: the patterns defined by geometry rather than by noise (see
 * kinds.h): the block patterns (checker, hexagon, brick, cubic, square,
 * triangular, object), the distance patterns (boxed, cylindrical,
 * spherical, planar, onion), gradient, radial, the spirals, quilted,
 * leopard, the normal-dependent slope and aoi, and the patterns that defer
 * to something else (function, pigment_pattern, image_pattern).
 *
 * Every formula was checked against POV-Ray 3.7 by printing
 * function { pattern { ... } } at hundreds of points (tests/unit/test_pattern.c
 * holds a sample); the comments say what was measured where the manual is
 * silent. Values are raw: frequency, phase and the wave are pattern.c's. */
#include "pattern/kinds.h"

#include "image/image.h"
#include "scene/fn.h"
#include "scene/object.h"
#include "scene/texture.h"

#include <math.h>

static const double PI = 3.14159265358979323846;
static const double SQRT3 = 1.73205080756887729353;

/* POV-Ray nudges coordinates up by 1e-10 before taking the cell of a
 * block pattern, so that a point on a face belongs to the cell above it
 * even after rounding (measured: checker changes colour at x = -1e-10,
 * not at -1e-11). */
static const double BLOCK_EPS = 1e-10;

/* The colour index of a checker: the parity of the sum of the cells. The
 * sum is a whole number, so s - 2 floor(s/2) is exactly fabs(fmod(s, 2))
 * (0 or 1; NaN for infinite coordinates), without fmod's library call. */
PATTERN_FN(checker)
{
	(void)pt; (void)ctx;
	double s = floor(q.x + BLOCK_EPS) + floor(q.y + BLOCK_EPS) + floor(q.z + BLOCK_EPS);
	return fabs(s - 2.0 * floor(0.5 * s));
}

/* Hexagons in the x-z plane with unit sides, flat sides facing ±z: centres
 * at (1.5 i, √3 (j + i/2)); the one at the origin is colour 0, the one at
 * (0, √3) colour 1, the ones at (±1.5, √3/2) colour 2. The cell is the
 * nearest centre. */
PATTERN_FN(hexagon)
{
	(void)pt; (void)ctx;
	double x = q.x, z = q.z;
	double fi = floor(x / 1.5);
	double best = INFINITY;
	double bi = 0, bj = 0;
	for (int di = 0; di <= 1; di++) {
		double i = fi + di;
		double j = floor(z / SQRT3 - i * 0.5 + 0.5);
		for (int dj = -1; dj <= 1; dj++) {
			double jj = j + dj;
			double cx = 1.5 * i, cz = SQRT3 * (jj + i * 0.5);
			double d = (x - cx) * (x - cx) + (z - cz) * (z - cz);
			if (d < best) {
				best = d;
				bi = i;
				bj = jj;
			}
		}
	}
	double c = fmod(bj + 2.0 * bi, 3.0);
	if (c < 0)
		c += 3.0;
	return c;
}

/* Layers of bricks pt->vec (x long, y high, z deep; default 8 × 3 × 4.5)
 * with mortar pt->vec2.x (0.5) on the high side of each brick. Measured:
 * in layers of even index the joints along z are moved by half a brick
 * depth, in odd layers the joints along x by half a brick length. 0 is
 * mortar, 1 brick. */
PATTERN_FN(brick)
{
	(void)ctx;
	vec3 s = pt->vec;
	double m = pt->vec2.x;
	double x = q.x + BLOCK_EPS, y = q.y + BLOCK_EPS, z = q.z + BLOCK_EPS;
	double layer = floor(y / s.y);
	if (fmod(layer, 2.0) == 0.0)
		z += s.z * 0.5;
	else
		x += s.x * 0.5;
	double fx = x - s.x * floor(x / s.x);
	double fy = y - s.y * floor(y / s.y);
	double fz = z - s.z * floor(z / s.z);
	if (fx >= s.x - m || fy >= s.y - m || fz >= s.z - m)
		return 0;
	return 1;
}

/* The six pyramids around the half-axes: +x 0, +y 1, +z 2, -x 3, -y 4,
 * -z 5. On a tie the first of that order wins (measured: (-1, 1, 0) is 1,
 * (-1, 0, 1) is 2, (-1, -1, 0) is 3). */
PATTERN_FN(cubic)
{
	(void)pt; (void)ctx;
	double c[6] = {q.x, q.y, q.z, -q.x, -q.y, -q.z};
	int best = 0;
	for (int i = 1; i < 6; i++)
		if (c[i] > c[best])
			best = i;
	return best;
}

/* Unit squares in the x-z plane in four colours, each square's four
 * neighbours different from it. Measured: with (a, b) the parities of the
 * cell's x and z, (0, 0) is entry 0, (0, 1) entry 1, (1, 1) entry 2 and
 * (1, 0) entry 3. */
PATTERN_FN(square)
{
	(void)pt; (void)ctx;
	double ix = floor(q.x + BLOCK_EPS), iz = floor(q.z + BLOCK_EPS);
	/* (the parities by comparison: an infinite coordinate gives NaN) */
	int a = fabs(fmod(ix, 2.0)) == 1.0, b = fabs(fmod(iz, 2.0)) == 1.0;
	static const int entry[2][2] = {{0, 1}, {3, 2}};
	return entry[a][b];
}

/* Equilateral triangles with unit sides in the x-z plane, an edge on
 * z = 0, in six colours: the six triangles around every vertex are the
 * six entries. In the sheared coordinates u = x - z/sqrt(3), w = z/(sqrt(3)/2)
 * the lattice is unit squares, each cut by its diagonal into a triangle
 * pointing to +z (fu + fw < 1) and one pointing to -z. Measured: along the
 * row 0 <= z < sqrt(3)/2 from x = 0 the triangles are entries 0 3 4 5 2 1,
 * repeating every 3 units, and each row down moves that sequence one
 * square of u to the left. */
PATTERN_FN(triangular)
{
	(void)pt; (void)ctx;
	double w = q.z / (SQRT3 * 0.5) + BLOCK_EPS;
	double u = q.x - q.z / SQRT3 + BLOCK_EPS;
	double row = floor(w), col = floor(u);
	bool up = (u - col) + (w - row) < 1.0;
	double m = fmod(col - row, 3.0);
	int k = fabs(m) < 3.0 ? (int)m : 0; /* NaN at an infinite coordinate */
	if (k < 0)
		k += 3;
	static const int up_entry[3] = {0, 4, 2}, down_entry[3] = {3, 5, 1};
	return up ? up_entry[k] : down_entry[k];
}

/* 1 inside the object, 0 outside. */
PATTERN_FN(object)
{
	(void)ctx;
	if (!pt->obj)
		return 0;
	return object_inside(pt->obj, q) ? 1 : 0;
}

PATTERN_FN(boxed)
{
	(void)pt; (void)ctx;
	double m = fmax(fabs(q.x), fmax(fabs(q.y), fabs(q.z)));
	return 1.0 - fmin(1.0, m);
}

PATTERN_FN(cylindrical)
{
	(void)pt; (void)ctx;
	return 1.0 - fmin(1.0, sqrt(q.x * q.x + q.z * q.z));
}

PATTERN_FN(spherical)
{
	(void)pt; (void)ctx;
	return 1.0 - fmin(1.0, sqrt(q.x * q.x + q.y * q.y + q.z * q.z));
}

PATTERN_FN(planar)
{
	(void)pt; (void)ctx;
	return 1.0 - fmin(1.0, fabs(q.y));
}

/* What gradient and function do with their value: one above 1 is reduced
 * modulo 1 (exactly 1 stays 1); a negative one is left for the frequency
 * step (pattern.c), which is what makes gradient x give 0.00001 at x = -2
 * in POV-Ray and 1 at x = 1 (measured). */
static double wrap_above_one(double v)
{
	return v > 1.0 ? fmod(v, 1.0) : v;
}

/* The distance along the unit direction of pt->vec. */
PATTERN_FN(gradient)
{
	(void)ctx;
	double l = v3_len(pt->vec);
	if (l == 0.0)
		return 0;
	return wrap_above_one(v3_dot(q, pt->vec) / l);
}

/* The distance from the origin modulo 1. */
PATTERN_FN(onion)
{
	(void)pt; (void)ctx;
	return fmod(sqrt(q.x * q.x + q.y * q.y + q.z * q.z), 1.0);
}

/* The angle around +y, measured: 0.5 at -x, 0.75 at +z, 1 at +x, 1.25 at
 * -z (so above 1 between +x and -z, which the frequency step reduces
 * modulo 1.00001), and 0.25 wherever |x| and |z| are both below 0.001. */
PATTERN_FN(radial)
{
	(void)pt; (void)ctx;
	if (fabs(q.x) < 0.001 && fabs(q.z) < 0.001)
		return 0.25;
	return 0.75 + atan2(q.x, q.z) / (2.0 * PI);
}

/* spiral1's value before the wave: height plus distance from the z axis
 * plus the arms times the angle around the axis as a fraction of a turn,
 * in [0, 1), 0 along -y and 0.25 along +x (measured); on the axis the
 * angle is 0. */
static double spiral_value(const struct pattern *pt, vec3 q, double *r_out)
{
	double r = sqrt(q.x * q.x + q.y * q.y);
	double v = q.z + r;
	if (r != 0.0) {
		double a = atan2(q.x, -q.y) / (2.0 * PI);
		if (a < 0)
			a += 1.0;
		v += pt->n[0] * a;
	}
	*r_out = r;
	return v;
}

/* The triangle fold of the fraction of v: 0 → 0, 0.5 → 1, 1 → 0. */
static double fold(double v)
{
	v = (v - floor(v)) * 2.0;
	return v > 1.0 ? 2.0 - v : v;
}

PATTERN_FN(spiral1)
{
	(void)ctx;
	double r;
	return spiral_value(pt, q, &r);
}

/* Two spirals winding in opposite directions: measured to be the triangle
 * fold of spiral1's value plus the triangle fold of the distance from the
 * axis. */
PATTERN_FN(spiral2)
{
	(void)ctx;
	double r;
	double v = spiral_value(pt, q, &r);
	return fold(r) + fold(v);
}

/* The cubic Bézier from 0 to 1 with inner control values c0 and c1. */
static double quilt_cubic(double t, double c0, double c1)
{
	double it = 1.0 - t;
	return c0 * 3.0 * t * it * it + c1 * 3.0 * t * t * it + t * t * t;
}

/* In each unit cube, the offset d from the centre scaled by the cubic of
 * its length; the value is the sum of the scaled offset's magnitudes
 * times 1.154700538 / 3. (That constant, 2/√3 to ten digits, fits POV-Ray's
 * values to the last printed digit: 0.374999999877 at a cube's corner with
 * control0 = control1 = 0.) */
PATTERN_FN(quilted)
{
	(void)ctx;
	vec3 d = v3(q.x - floor(q.x) - 0.5, q.y - floor(q.y) - 0.5, q.z - floor(q.z) - 0.5);
	double t = v3_len(d);
	/* control0 and control1 are single precision in POV-Ray (measured:
	 * control0 0.3 differs from the double formula in the ninth digit) */
	double k = quilt_cubic(t, (float)pt->f[0], (float)pt->f[1]);
	double s = fabs(d.x * k) + fabs(d.y * k) + fabs(d.z * k);
	return s * 1.154700538 / 3.0;
}

PATTERN_FN(leopard)
{
	(void)pt; (void)ctx;
	double s = (sin(q.x) + sin(q.y) + sin(q.z)) / 3.0;
	return s * s;
}

/* slope { <Direction> [, lo, hi] [altitude <Altitude> [, lo, hi]] }:
 * pt->vec the direction, pt->vec2 the altitude (zero: none), pt->f[0..1]
 * the slope range, pt->f[2..3] the altitude range (equal: 0 to 1);
 * pt->n[1] = 1 for `point_at` (pt->vec the point). The slope is 0.5 + 0.5
 * cos of the angle between the normal and the direction; with an altitude
 * the result is the average of slope and altitude weighted by the lengths
 * of the two vectors. */
PATTERN_FN(slope)
{
	/* The slope is taken in world space: POV-Ray ignores the pattern's
	 * transformations for it (measured: slope { y } rotate z*40 is still
	 * the angle from world y, and point_at's direction is from the world
	 * point); only the altitude part follows them. */
	vec3 n = v3_norm(ctx->normal);
	double dl = v3_len(pt->vec);
	vec3 dir;
	if (pt->n[1] == 1) {
		dir = v3_sub(pt->vec, ctx->p);
		double l = v3_len(dir);
		dir = l > 0 ? v3_scale(dir, 1.0 / l) : v3(0, 1, 0);
		dl = 1.0;
	} else {
		dir = dl > 0 ? v3_scale(pt->vec, 1.0 / dl) : v3(0, 1, 0);
	}
	/* linear in the angle (measured: 1 - angle/pi to 1e-5 over a sphere,
	 * for a direction and for point_at; not 0.5 + 0.5 cos) */
	double c = v3_dot(n, dir);
	double s = 1.0 - acos(c > 1 ? 1 : c < -1 ? -1 : c) / PI;
	double lo = pt->f[0], hi = pt->f[1];
	if (hi != lo)
		s = (s - lo) / (hi - lo);
	double al = v3_len(pt->vec2);
	if (al == 0.0 || pt->n[1] == 1)
		return s;
	double a = v3_dot(q, pt->vec2) / al;
	double alo = pt->f[2], ahi = pt->f[3];
	if (ahi != alo)
		a = (a - alo) / (ahi - alo);
	return (s * dl + a * al) / (dl + al);
}

/* The angle of incidence: 1 where the ray meets the surface head-on, 0.5
 * where it grazes it (1 - angle/π between the reversed ray and the
 * normal). */
PATTERN_FN(aoi)
{
	(void)pt; (void)q;
	double c = -v3_dot(ctx->dir, ctx->normal);
	if (c > 1.0)
		c = 1.0;
	if (c < -1.0)
		c = -1.0;
	return 1.0 - acos(c) / PI;
}

/* The user function at (x, y, z); further parameters are 0. */
PATTERN_FN(function)
{
	(void)ctx;
	if (!pt->fn)
		return 0;
	double args[FN_MAX_PARAMS] = {q.x, q.y, q.z};
	return wrap_above_one(fn_eval(pt->fn, args));
}

/* The grey of the pigment at q (POV-Ray's weights for red, green, blue). */
PATTERN_FN(pigment)
{
	if (!pt->pig)
		return 0;
	struct pattern_ctx c = *ctx;
	c.p = q;
	struct rgbft col = pigment_eval(pt->pig, &c);
	return 0.297 * col.r + 0.589 * col.g + 0.114 * col.b;
}

PATTERN_FN(image)
{
	(void)ctx;
	if (!pt->img.img)
		return 0;
	return image_map_value(&pt->img, q);
}

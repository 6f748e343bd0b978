/* fn_internal.c: POV-Ray's internal functions, the ones a scene reaches
 * through `function { internal(N) }` and that POV-Ray's functions.inc names
 * f_sphere, f_torus, f_helix1 and so on.
 *
 * The numbering and the parameter lists are POV-Ray 3.7's. Each function
 * receives x, y, z and then its own parameters P0, P1, ... in one array.
 * The manual (the functions.inc section of the include-files chapter) names
 * the functions and their parameters; the formulas were worked out by
 * evaluating POV-Ray 3.7 at many points and written anew from that. The
 * deterministic functions reproduce POV-Ray's values to rounding for any
 * parameters, negative, zero and fractional ones included, NaN and
 * infinite results too (tests/unit/fn_internal_sweep.sh compares them on
 * random cases; the unit test holds recorded values). An exact zero has
 * POV-Ray's sign: the order of the terms and where a negation sits decide
 * it, and they were chosen by measuring (zero and -0 coordinates and
 * parameters, terms that cancel exactly; tests/lang/stdlib-functions-exact).
 * What is left: where a value is a small difference of large terms, some
 * functions (f_hex_y, f_quantum, f_spikes) agree to the rounding
 * of the terms only; with -0 coordinates f_comma, f_helical_torus,
 * f_helix1 and f_spiral can differ from POV-Ray (their angle branches),
 * and a zero of f_spiral can have the other sign.
 * f_noise3d and f_noise_generator are POV-Ray's noise (the patterns'
 * noise3), and so are f_hetero_mf and f_ridge (tests/lang/
 * stdlib-functions-noise) and f_ridged_mf (within what POV-Ray keeps from
 * its first call: see there).
 *
 * Conventions that many functions share:
 *   - "field strength" functions return P0 times a polynomial, clamped to
 *     [-10, 10] (field()). Most are POV-Ray's -P0 * g, g the polynomial
 *     of the opposite sign (field(P0, -(g)) here): g's form is POV-Ray's
 *     where the sign of a zero or the rounding showed it (expanded or
 *     factored, the order of the terms);
 *   - the "_2d" functions describe a curve in the xy plane; with their SOR
 *     switch above zero the curve is swept around the y axis instead of
 *     being extruded along z (sor());
 *   - helix, spiral and the like measure their cross section with a norm
 *     chosen by a "cross section type" parameter (section_norm()). */
#include "scene/fn.h"
#include "pattern/pattern.h"

#include <math.h>
#include <stdint.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define SQRT2 1.41421356237309504880

/* The bound that POV-Ray puts on the "field strength" functions. */
#define FIELD_LIMIT 10.0

static double sq(double v)
{
	return v * v;
}

/* (int)v as x86 makes it, which POV-Ray's fractions of octaves take:
 * INT_MIN out of an int's range and for NaN (the C cast is undefined
 * there). */
static double x86_int(double v)
{
	return v > -2147483649.0 && v < 2147483648.0 ? (double)(int)v : -2147483648.0;
}

/* v truncated toward zero as C's cast does, but kept within [-limit,
 * limit] (and 0 for NaN) so that the cast is always defined. Counts of
 * tubes and octaves go through it, so a wild parameter cannot make a
 * function loop for long. */
static int to_int(double v, int limit)
{
	if (!(v == v))
		return 0;
	if (v > limit)
		return limit;
	if (v < -limit)
		return -limit;
	return (int)v;
}

/* P0 * v, clamped to [-FIELD_LIMIT, FIELD_LIMIT]. */
static double field(double p0, double v)
{
	double r = p0 * v;
	if (r > FIELD_LIMIT)
		r = FIELD_LIMIT;
	if (r < -FIELD_LIMIT)
		r = -FIELD_LIMIT;
	return r;
}

/* The SOR transformation of the "_2d" functions: with the switch above
 * zero, (x, y) becomes the distance from the y axis less the offset and y,
 * rotated by angle degrees about z (not rotated at all for a zero angle,
 * which keeps the sign of a zero y as POV-Ray does). Otherwise x and y are
 * left as they are (the curve is extruded along z). */
static void sor(const double *a, double sw, double offset, double angle,
		double *px, double *py)
{
	double x = a[0], y = a[1];
	if (sw > 0) {
		double u = sqrt(a[0] * a[0] + a[2] * a[2]) - offset;
		x = u;
		if (angle != 0) {
			double t = angle * (M_PI / 180);
			x = u * cos(t) - y * sin(t);
			y = u * sin(t) + y * cos(t);
		}
	}
	*px = x;
	*py = y;
}

/* The norm of a cross section offset (u, v) for the helix and spiral
 * functions' "cross section type" t: 0 is a square (the max norm), 1 a
 * circle, 2 a diamond, and in general the L(2/t) norm. NaN in, NaN out,
 * as in POV-Ray (its spiral with zero spacing gives NaN here). */
static double section_norm(double u, double v, double t)
{
	u = fabs(u);
	v = fabs(v);
	if (t == 0)
		return u > v || u != u ? u : v;
	double p = 2 / t;
	return pow(pow(u, p) + pow(v, p), 1 / p);
}

/* ---- the algebraic cylinders (0-3): P0 field strength, P1 field limit,
 * P2-P4 the SOR switch, offset and angle ---- */

/* POV-Ray's min and max of two values: the first one unless the second is
 * strictly smaller (larger). Where the two compare equal (0 and -0) or the
 * second is NaN, the first is the result, which decides the sign of a zero
 * result as in POV-Ray. */
static double min_first(double a, double b)
{
	return b < a ? b : a;
}

static double max_first(double a, double b)
{
	return a < b ? b : a;
}

/* P0 * curve kept within [-P1, P1]. A negative limit leaves an empty
 * range, and POV-Ray's order of the two bounds decides the value:
 * f_algbr_cyl1 applies the upper bound first and gives -P1, the other
 * three the lower bound first and give P1 (measured, as are the signs of
 * a zero result with a zero limit). */
static double algbr_cyl(const double *a, double curve, int upper_first)
{
	double r = a[3] * curve, lim = a[4];
	if (upper_first)
		return max_first(-lim, min_first(lim, r));
	return min_first(lim, max_first(-lim, r));
}

static double f_algbr_cyl1(const double *a)
{
	double x, y;
	sor(a, a[5], a[6], a[7], &x, &y);
	return algbr_cyl(a, x * x * (fabs(x) - 1) + y * y, 1);
}

static double f_algbr_cyl2(const double *a)
{
	double x, y;
	sor(a, a[5], a[6], a[7], &x, &y);
	double x2 = x * x, y2 = y * y;
	return algbr_cyl(a, -(y2 - 3 * x2 * y - 2 * y2 * y + 2 * x2 * x2 + y2 * y2), 0);
}

static double f_algbr_cyl3(const double *a)
{
	double x, y;
	sor(a, a[5], a[6], a[7], &x, &y);
	double x2 = x * x, y2 = y * y;
	return algbr_cyl(a, -(y2 - 2 * x2 * y - x * y2 + x2 * x2 + x2 * y2), 0);
}

static double f_algbr_cyl4(const double *a)
{
	double x, y;
	sor(a, a[5], a[6], a[7], &x, &y);
	double x2 = x * x, y2 = y * y;
	return algbr_cyl(a, -(3 * x2 * y - y2 * y + sq(x2 + y2)), 0);
}

/* ---- field strength surfaces: P0 field strength, then shape
 * parameters ---- */

static double f_bicorn(const double *a)
{
	double x = a[0], y = a[1], z = a[2], s = a[4];
	double r2 = x * x + z * z;
	return field(a[3], y * y * (s * s - r2) - sq(r2 + 2 * s * y - s * s));
}

static double f_bifolia(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double r2 = x * x + z * z;
	return field(a[3], -(sq(r2 + y * y) - a[4] * y * r2));
}

/* Apery's sextic for Boy's surface, scaled by P1. */
static double f_boy_surface(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double x2 = x * x, y2 = y * y, z2 = z * z, h = x2 + y2;
	double w = 1 - z;
	double v = 64 * w * w * w * z2 * z
		- 48 * w * w * z2 * (3 * h + 2 * z2)
		+ 12 * w * z * (27 * h * h - 24 * z2 * h
				+ 36 * SQRT2 * y * z * (y2 - 3 * x2) + 4 * z2 * z2)
		+ (9 * h - 2 * z2) * (-81 * h * h - 72 * z2 * h
				+ 108 * SQRT2 * x * z * (x2 - 3 * y2) + 4 * z2 * z2);
	return field(a[3], a[4] * v);
}

static double f_crossed_trough(const double *a)
{
	return field(a[3], a[0] * a[0] * a[2] * a[2] - a[1]);
}

static double f_cubic_saddle(const double *a)
{
	double x = a[0], y = a[1];
	return field(a[3], -(x * x * x - y * y * y - a[2]));
}

/* f_cushion and f_odd are the same function in POV-Ray 3.7. */
static double f_cushion(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z = a[2], z2 = z * z;
	double v = x2 + y2 - 2 * z2 + 2 * y2 * z + 2 * z2 * z
		- sq(x2 + y2) + x2 * z2 - y2 * z2 - z2 * z2;
	return field(a[3], v);
}

static double f_devils_curve(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	return field(a[3], -(sq(x2 + z2) - y2 * y2 - 0.36 * x2 + 0.25 * y2));
}

static double f_devils_curve_2d(const double *a)
{
	double x, y;
	sor(a, a[6], a[7], a[8], &x, &y);
	double x2 = x * x, y2 = y * y;
	return field(a[3], -(x2 * (x2 - a[4] * a[4]) - y2 * (y2 - a[5] * a[5])));
}

/* A torus of radii P1, P2 displaced by (P3, P4, 0) and inverted in a
 * sphere of radius P5, cleared of denominators. The last term is part of
 * POV-Ray's polynomial although it does not follow from the inversion. */
static double f_dupin_cyclid(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double R = a[4], r = a[5], dx = a[6], dy = a[7], k = a[8];
	double k2 = k * k, r2 = x * x + y * y + z * z;
	double c = dx * dx + dy * dy + R * R - r * r;
	double s = k2 * k2 - 2 * k2 * (x * dx + y * dy) + c * r2;
	double v = s * s - 4 * R * R * (sq(k2 * x - dx * r2) + k2 * k2 * z * z)
		+ 8 * (R * R - r * r) * dy * k2 * y * r2;
	return field(a[3], -v);
}

/* Enneper's surface. The z in the denominators is kept at least 0.2 away
 * from zero (POV-Ray uses 0.2 for |z| < 0.2, whatever z's sign). */
static double f_enneper(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double u = x * x - y * y;
	double zd = fabs(z) < 0.2 ? 0.2 : z;
	double c = z * z * (2.0 / 9) - u / (2 * zd);
	return field(a[3], -(c * c * c - 6 * sq(u / (4 * zd))));
}

static double f_folium_surface(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double n = a[4], d = a[5];
	return field(a[3], (y * y + z * z) * (1 + (d - 4 * n) * x) + x * x * (1 + d));
}

static double f_folium_surface_2d(const double *a)
{
	double x, y;
	sor(a, a[6], a[7], a[8], &x, &y);
	double n = a[4], d = a[5];
	return field(a[3], -(y * y * (1 + (d - 4 * n) * x) + x * x * (1 + d)));
}

static double f_glob(const double *a)
{
	double x = a[0], x4 = x * x * x * x;
	return field(a[3], 0.5 * x4 * (1 + x) - a[1] * a[1] - a[2] * a[2]);
}

static double f_heart(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z = a[2], z2 = z * z;
	double b = 2 * x2 + y2 + z2 - 1;
	return field(a[3], -(b * b * b - (0.1 * x2 + y2) * z2 * z));
}

static double f_hunt_surface(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double b = x2 + y2 + z2 - 13;
	return field(a[3], -(4 * b * b * b + 27 * sq(3 * x2 + y2 - 4 * z2 - 12)));
}

/* (x2 + y2 - z2 + R2 - r2)^2 - 4 R2 (x2 - z2), expanded and grouped as
 * POV-Ray evaluates it: its values agree bit for bit where the terms
 * nearly cancel. */
static double f_hyperbolic_torus(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double R2 = a[4] * a[4], r2 = a[5] * a[5];
	double g = x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * x2 * (R2 + r2)
		+ y2 * y2 - 2 * y2 * z2 + 2 * y2 * (R2 - r2)
		+ z2 * z2 + 2 * z2 * (R2 + r2) + sq(R2 - r2);
	return field(a[3], -g);
}

static double f_kampyle_of_eudoxus(const double *a)
{
	double x2 = a[0] * a[0], d = a[4], c = a[5];
	return field(a[3], -(a[1] * a[1] + a[2] * a[2] - c * c * x2 * (x2 - d * d)));
}

static double f_kampyle_of_eudoxus_2d(const double *a)
{
	double x, y;
	sor(a, a[6], a[7], a[8], &x, &y);
	double x2 = x * x, d = a[4], c = a[5];
	return field(a[3], -(y * y - c * c * x2 * x2 + d * c * c * c * x2));
}

/* The Klein bottle's sextic, negated. */
static double f_klein_bottle(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double r2 = x * x + y * y + z * z;
	double m = r2 - 2 * y - 1;
	return field(a[3], -((r2 + 2 * y - 1) * (m * m - 8 * z * z) + 16 * x * z * m));
}

static double f_kummer_surface_v1(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double g = x2 * x2 + y2 * y2 + z2 * z2 - x2 * y2 - x2 * z2 - y2 * z2
		- x2 - y2 - z2 + 1;
	return field(a[3], -g);
}

static double f_kummer_surface_v2(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double x2 = x * x, y2 = y * y, z2 = z * z;
	double g = a[4] * (x2 + y2 + z2) + (x2 * x2 + y2 * y2 + z2 * z2)
		+ a[6] * x * y * z + a[5] * (x2 * y2 + x2 * z2 + y2 * z2) - 1;
	return field(a[3], -g);
}

static double f_lemniscate_of_gerono(const double *a)
{
	double x2 = a[0] * a[0];
	return field(a[3], -(x2 * x2 - x2 + a[1] * a[1] + a[2] * a[2]));
}

static double f_lemniscate_of_gerono_2d(const double *a)
{
	double x, y;
	sor(a, a[6], a[7], a[8], &x, &y);
	double x2 = x * x, s = a[4], w = a[5];
	return field(a[3], -(y * y - w * w * x2 * (s * s - x2)));
}

static double f_mitre(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	return field(a[3], -(4 * x2 * (x2 + y2 + z2) + y2 * (y2 + z2) - y2));
}

static double f_nodal_cubic(const double *a)
{
	double y = a[1], z = a[2];
	return field(a[3], -(y * y * y + z * z * z - 6 * y * z));
}

static double f_ovals_of_cassini(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double R2 = a[4] * a[4], fill = a[5], thick = a[6];
	return field(a[3], -(sq(x2 + y2 + z2 + R2) - fill * fill - thick * R2 * (x2 + z2)));
}

static double f_paraboloid(const double *a)
{
	return field(a[3], -(a[0] * a[0] + a[2] * a[2] - a[1]));
}

static double f_parabolic_torus(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1];
	double R2 = a[4] * a[4], r2 = a[5] * a[5];
	double w = x2 + y2 - a[2];
	return field(a[3], -(w * w - (R2 + r2) * w + 2 * R2 * y2 + sq(R2 - r2)));
}

static double f_pillow(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	return field(a[3], x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2);
}

static double f_piriform(const double *a)
{
	double x = a[0], x3 = x * x * x;
	return field(a[3], x3 * x - x3 + a[1] * a[1] + a[2] * a[2]);
}

static double f_piriform_2d(const double *a)
{
	double x, y;
	sor(a, a[7], a[8], a[9], &x, &y);
	double x3 = x * x * x, f = a[6];
	return field(a[3], -(y * y - f * f * (a[4] * x3 + a[5] * x3 * x)));
}

static double f_quartic_paraboloid(const double *a)
{
	double x2 = a[0] * a[0], z2 = a[2] * a[2];
	return field(a[3], -(x2 * x2 + z2 * z2 - a[1]));
}

static double f_quartic_saddle(const double *a)
{
	double x2 = a[0] * a[0], z2 = a[2] * a[2];
	return field(a[3], -(x2 * x2 - z2 * z2 - a[1]));
}

static double f_quartic_cylinder(const double *a)
{
	double d = a[4], w = a[5];
	double r2 = a[0] * a[0] + a[2] * a[2];
	return field(a[3], -(r2 * (a[1] * a[1] + w * w) - d * d * w * w));
}

static double f_steiners_roman(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double x2 = x * x, y2 = y * y, z2 = z * z;
	return field(a[3], -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z));
}

static double f_strophoid(const double *a)
{
	double x = a[0], yz = a[1] * a[1] + a[2] * a[2];
	double f = a[6];
	return field(a[3], -((a[5] - x) * yz - f * f * x * x * x - f * f * a[4] * x * x));
}

static double f_strophoid_2d(const double *a)
{
	double x, y;
	sor(a, a[7], a[8], a[9], &x, &y);
	double f = a[6];
	return field(a[3], -(y * y * (a[5] - x) - f * f * x * x * x - f * f * a[4] * x * x));
}

/* (x2 + y2 + z2 + R2 - r2)^2 - 4 R2 (x2 + z2), expanded and grouped as
 * POV-Ray evaluates it (bit for bit where the terms nearly cancel). */
static double f_torus2(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double R2 = a[4] * a[4], r2 = a[5] * a[5];
	double g = x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2
		+ 2 * y2 * z2 - 2 * x2 * (R2 + r2) + 2 * y2 * (R2 - r2)
		- 2 * z2 * (R2 + r2) + sq(R2 - r2);
	return field(a[3], -g);
}

static double f_torus_gumdrop(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double v = -17 + 20 * (x2 + y2 + z2) - 4 * (x2 * x2 + y2 * y2 + z2 * z2)
		- 17 * x2 * (y2 + z2) - 8 * y2 * z2;
	return field(a[3], v);
}

static double f_umbrella(const double *a)
{
	return field(a[3], -(a[0] * a[0] - a[1] * a[2] * a[2]));
}

static double f_witch_of_agnesi(const double *a)
{
	double y = a[1], w = a[4];
	return field(a[3], -(y * (a[0] * a[0] + a[2] * a[2]) - w * (1 - y)));
}

static double f_witch_of_agnesi_2d(const double *a)
{
	double x, y;
	sor(a, a[6], a[7], a[8], &x, &y);
	return field(a[3], -(y * (x * x + a[4] * a[4]) - a[5]));
}

/* ---- blobs and ellipsoid families ---- */

/* One component of f_blob: (1 - d2)^2 inside the unit radius. */
static double blob_density(double d2)
{
	return d2 < 1 ? sq(1 - d2) : 0;
}

/* Two components at (-P0/2, 0, 0) and (P0/2, 0, 0) with strengths P1, P3
 * and inverse radii P2, P4. */
static double f_blob(const double *a)
{
	double x = a[0], yz = a[1] * a[1] + a[2] * a[2], h = a[3] / 2;
	double d1 = (sq(x + h) + yz) * a[5] * a[5];
	double d2 = (sq(x - h) + yz) * a[7] * a[7];
	return -(a[4] * blob_density(d1) + a[6] * blob_density(d2));
}

/* Gaussian components at the origin and at (P0, 0, 0). */
static double f_blob2(const double *a)
{
	double x = a[0], yz = a[1] * a[1] + a[2] * a[2];
	double g = exp(-a[4] * (x * x + yz)) + exp(-a[4] * (sq(x - a[3]) + yz));
	return a[6] - a[5] * g;
}

/* The three gaussian ellipsoids of f_cross_ellipsoids, f_isect_ellipsoids
 * and f_flange_cover, each long along one axis: P0 is the eccentricity and
 * P1 the inverse size. */
static void ellipsoids3(const double *a, double e[3])
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double ecc = a[3], s = a[4];
	e[0] = exp(-s * (x2 + ecc * (y2 + z2)));
	e[1] = exp(-s * (y2 + ecc * (x2 + z2)));
	e[2] = exp(-s * (z2 + ecc * (x2 + y2)));
}

static double f_cross_ellipsoids(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	double m = fmax(e[0], fmax(e[1], e[2]));
	return a[6] - a[5] * m;
}

static double f_isect_ellipsoids(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	double m = fmin(e[0], fmin(e[1], e[2]));
	return a[6] - a[5] * m;
}

static double f_flange_cover(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	return a[6] - a[5] * (e[0] + e[1] + e[2]);
}

static double f_ellipsoid(const double *a)
{
	return sqrt(sq(a[0] * a[3]) + sq(a[1] * a[4]) + sq(a[2] * a[5]));
}

/* P2 times the sum of three ellipsoids (as in f_flange_cover, with P0 the
 * eccentricity and P1 the inverse size) less P4 times a gaussian sphere of
 * inverse size P3. */
static double f_spikes(const double *a)
{
	double x2 = a[0] * a[0], y2 = a[1] * a[1], z2 = a[2] * a[2];
	double sharp = a[3], s = a[4];
	double ex = exp(-s * (x2 + sharp * (y2 + z2)));
	double ey = exp(-s * (y2 + sharp * (x2 + z2)));
	double ez = exp(-s * (z2 + sharp * (x2 + y2)));
	double ball = a[7] * exp(-a[6] * (x2 + y2 + z2));
	/* The terms taken from the ball in this order, and the whole negated:
	 * POV-Ray's rounding where they nearly cancel, and its sign of a zero
	 * or of a NaN (0 * inf) result (measured). */
	return a[5] * -(ball - ez - ey - ex);
}

static double f_spikes_2d(const double *a)
{
	double x = a[0], z = a[2];
	return -(a[3] * cos(a[4] * x) * cos(a[5] * z) * exp(-a[6] * (x * x + z * z)) - a[1]);
}

/* A d orbital's density cloud; P0 is not used. On the y axis x counts as
 * 1e-6 (POV-Ray's values there). */
static double f_quantum(const double *a)
{
	double x = a[0] == 0 && a[2] == 0 ? 1e-6 : a[0];
	double x2 = x * x, y2 = a[1] * a[1], z2 = a[2] * a[2];
	double r = sqrt(x2 + y2 + z2);
	return 1.2 - 1.6 * sq(2 * y2 - x2 - z2) * exp(-1.33333332 * r);
}

/* ---- simple shapes and coordinates ---- */

static double f_ph(const double *a)
{
	return atan2(sqrt(a[0] * a[0] + a[2] * a[2]), a[1]);
}

static double f_r(const double *a)
{
	return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

static double f_th(const double *a)
{
	return atan2(a[0], a[2]);
}

static double f_sphere(const double *a)
{
	return f_r(a) - a[3];
}

static double f_torus(const double *a)
{
	double d = sqrt(a[0] * a[0] + a[2] * a[2]) - a[3];
	return sqrt(d * d + a[1] * a[1]) - a[4];
}

/* A box of half sizes P1-P3 with edges rounded to radius P0. Inside, the
 * value is -P0 (not a signed distance); POV-Ray subtracts another 1e-6. */
static double f_rounded_box(const double *a)
{
	double r = a[3];
	double qx = fmax(fabs(a[0]) - a[4] + r, 0);
	double qy = fmax(fabs(a[1]) - a[5] + r, 0);
	double qz = fmax(fabs(a[2]) - a[6] + r, 0);
	return sqrt(qx * qx + qy * qy + qz * qz) - r - 1e-6;
}

static double f_superellipsoid(const double *a)
{
	double e = a[3], n = a[4];
	double xy = pow(fabs(a[0]), 2 / e) + pow(fabs(a[1]), 2 / e);
	return 1 - pow(pow(xy, e / n) + pow(fabs(a[2]), 2 / n), n / 2);
}

/* y polynomial of degree 4 with coefficients c[0..4] (constant first). */
static double poly4(const double *c, double y)
{
	return c[0] + y * (c[1] + y * (c[2] + y * (c[3] + y * c[4])));
}

/* The surface of revolution of x = poly(y); the polynomial is kept at
 * least -5. */
static double f_poly4(const double *a)
{
	double p = fmax(poly4(a + 3, a[1]), -5);
	return sqrt(a[0] * a[0] + a[2] * a[2]) - p;
}

/* The distance to the nearest of int(P0) tubes that each follow
 * x = poly(y) in a plane through the y axis, the planes 2 pi / P0 apart,
 * the first containing +z; 10000 when there are none. */
static double f_polytubes(const double *a)
{
	double x = a[0], z = a[2], n = a[3];
	double p = poly4(a + 4, a[1]);
	double best = 10000;
	int count = to_int(n, 100000);
	for (int k = 0; k < count; k++) {
		double t = 2 * M_PI * k / n;
		double d = hypot(x - p * sin(t), z - p * cos(t));
		if (d < best)
			best = d;
	}
	return best;
}

/* ---- lattices ---- */

/* The hexagon norm of the f_hex_x cells: flat sides across x. */
static double hex_norm(double dx, double dy)
{
	dx = fabs(dx);
	dy = fabs(dy);
	return fmax(dx, 0.5 * dx + 0.5 * sqrt(3.0) * dy);
}

/* Hexagonal prisms along z: the hexagon norm to the nearest point of the
 * triangular lattice with spacing sqrt(3) (points (sqrt 3 i, 3 j) and the
 * same shifted by (sqrt(3) / 2, 3 / 2)). P0 is not used. */
static double f_hex_x(const double *a)
{
	const double w = sqrt(3.0), h = 3.0;
	double x = a[0], y = a[1];
	double best = HUGE_VAL;
	for (int s = 0; s < 2; s++) {
		double ox = s ? w / 2 : 0, oy = s ? h / 2 : 0;
		double cx = ox + w * floor((x - ox) / w);
		double cy = oy + h * floor((y - oy) / h);
		for (int i = 0; i < 2; i++)
			for (int j = 0; j < 2; j++) {
				double d = hex_norm(x - cx - i * w, y - cy - j * h);
				if (d < best)
					best = d;
			}
	}
	return best;
}

/* The distance from v to the nearest multiple of p. */
static double wrap_dist(double v, double p)
{
	return fabs(v - p * floor(v / p + 0.5));
}

/* Three families of planes along z, 1.5 apart, across y and at +-60
 * degrees to it: the edges of a triangular lattice. P0 is not used. */
static double f_hex_y(const double *a)
{
	double x = a[0], y = a[1];
	double s = 0.5 * sqrt(3.0);
	return fmin(wrap_dist(y, 1.5),
			fmin(wrap_dist(s * x - 0.5 * y, 1.5), wrap_dist(s * x + 0.5 * y, 1.5)));
}

/* The distance from v to the nearest of the points off + (2k + 1) s (k
 * any integer), up to its sign, measured as POV-Ray does:
 * fmod(|v - off|, 2s) - s. For a positive s its size is the true distance;
 * for a negative s it is one spacing more (|v - off| mod 2|s| plus |s|,
 * measured from off alone), and a zero s gives NaN. All three are
 * POV-Ray's values. The caller squares it, which keeps the sign POV-Ray's
 * NaN has. */
static double thread_dist(double v, double s, double off)
{
	return fmod(fabs(v - off), 2 * s) - s;
}

/* Threads along z at x = i P0 and along x at z = j P1, weaving up and down
 * with amplitude P3; P2 scales the distance across a thread, P4 along y.
 * Each direction has two families of threads, those at odd multiples of
 * the spacing and those at even ones, which weave in opposite senses; the
 * value is the nearest thread's scaled distance. The formulas, negative
 * and zero spacings included, are POV-Ray's (measured: a negative spacing
 * puts each family's nearest thread one spacing further, see
 * thread_dist()). A NaN distance (zero spacing) stays the value only if it
 * comes first: later ones lose every comparison, as in POV-Ray. */
static double f_mesh1(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double sx = a[3], sz = a[4], wxz = a[5], amp = a[6], wy = a[7];
	double cz = amp * cos(z * (M_PI / sz)), cx = amp * cos(x * (M_PI / sx));
	const double d[4] = {thread_dist(x, sx, 0), thread_dist(x, sx, sx),
		thread_dist(z, sz, 0), thread_dist(z, sz, sz)};
	const double yc[4] = {cz, -cz, -cx, cx};
	double best = 0;
	for (int k = 0; k < 4; k++) {
		double v = sqrt(sq(d[k] * wxz) + sq((y - yc[k]) * wy));
		if (k == 0 || v < best)
			best = v;
	}
	return best;
}

/* ---- helices and spirals ---- */

/* P0 helices of period 2 pi / P1 in y, major radius P3, minor radius P2,
 * cross section stretched by P4 along y, of type P5 and turned by P6
 * degrees. The helices pass angle pi / P0 (from +x towards +z) at y = 0.
 * The cross section is measured in the plane through the y axis, its
 * vertical offset wrapped to the nearest turn; it never exceeds the
 * distance to the tube center on the far side of the axis. */
static double f_helix1(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double n = a[3], per = a[4], R = a[6];
	double rho = sqrt(x * x + z * z);
	double ph = atan2(z, x) + per * y;
	double k = floor(ph * n / (2 * M_PI));
	double d = (ph - (2 * M_PI * k + M_PI) / n) / per;
	double u = rho - R, v = d / a[7];
	if (a[9] != 0) {
		double t = a[9] * (M_PI / 180), ur = u * cos(t) - v * sin(t);
		v = u * sin(t) + v * cos(t);
		u = ur;
	}
	return fmin(section_norm(u, v, a[8]), rho + R) - a[5];
}

/* One helix: the point is turned by -P1 y about the y axis and measured in
 * the xz plane from (P3, 0) with a cross section of type P5; P0, P4 and P6
 * are not used. */
static double f_helix2(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double t = a[4] * y;
	double xr = x * cos(t) + z * sin(t);
	double zr = -x * sin(t) + z * cos(t);
	return section_norm(xr - a[6], zr, a[8]) - a[5];
}

/* An Archimedean spiral in the xz plane, P0 between windings, P1 thick,
 * cut off by a sphere of radius P2; P5 is the cross section type. The
 * cross section never exceeds the distance r from the origin, and on the y
 * axis r is measured as if x were 1e-6 (POV-Ray's values: at the origin
 * the spiral of zero thickness gives 1e-6). With a zero spacing the cross
 * section is NaN and the sphere alone gives the value (POV-Ray's), hence
 * the NaN-keeping comparison and fmax. */
static double f_spiral(const double *a)
{
	double x = a[0], y = a[1], z = a[2], d = a[3];
	double rho = sqrt(x * x + z * z);
	double u = fmod(rho + d * atan2(z, x) / (2 * M_PI), d) - d / 2;
	double s = section_norm(u, y, a[8]);
	double xr = x == 0 && z == 0 ? 1e-6 : x;
	double r = sqrt(xr * xr + y * y + z * z);
	if (s > r)
		s = r;
	return fmax(s - a[4], r - a[5]);
}

/* A torus of major radius P0 wound with P1 loops (POV-Ray's values at every
 * parameter set tried).
 *
 * Around the y axis the angle t is measured from +z towards -x, in (-pi,
 * pi] (the y axis itself counts as +x, t = -pi/2). Around the core circle
 * the point lies at distance d, at angle p from +y towards the outside.
 * The winding's coordinate w = P1 t + pi - P2 p, wrapped to (-pi, pi], is
 * zero on the winding: P1 separate rings, or with a twist P2 rings that
 * run into one another. Its cross section is
 * s = sqrt((d - P5)^2 + P6 w^2), never more than d + P5 (the distance to
 * the far side of a ring of radius P5), and it is P3 thick, a thickness
 * modulated by the grooves cos(P9 t + P7 atan2(P8 w, d - P5)). A column
 * rho + P0 - P5 around the y axis takes over where it is nearer; P4 is
 * subtracted from the whole.
 *
 * A negative P6 makes s NaN: the comparisons are written so that the
 * column is the value then, as in POV-Ray. */
static double f_helical_torus(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double R = a[3], loops = a[4], twist = a[5], fat = a[6], thr = a[7];
	double wr = a[8], fat2 = a[9], gper = a[10], gamp = a[11], gphase = a[12];
	double rho = sqrt(x * x + z * z);
	double t = atan2(z, x) - M_PI / 2;
	if (t < -M_PI)
		t += 2 * M_PI;
	double u = rho - R, d = sqrt(u * u + y * y);
	double w = loops * t + M_PI - twist * atan2(u, y);
	w -= 2 * M_PI * ceil(w / (2 * M_PI) - 0.5);
	double s = sqrt(sq(d - wr) + fat2 * w * w);
	if (s > d + wr)
		s = d + wr;
	double wind = s - fat * cos(gphase * t + gper * atan2(gamp * w, d - wr));
	double column = rho + R - wr;
	return (wind < column ? wind : column) - thr;
}

/* The comma of size P0 (s below): a ball of radius s / 2 at (s / 2, 0, 0)
 * and a tail, a tube around the circle of radius 3s / 4 about
 * (-s / 4, 0, 0) in the xz plane whose radius (s / 2) cos(a / 2) shrinks
 * with the angle a of the point about the origin, from the ball's at +x
 * to nothing at (-s, 0, 0); the tail is cut off below the plane z = 0.
 * On the y axis x counts as 0.0001, as in POV-Ray. A negative or zero P0
 * keeps the formula (POV-Ray's values are those). */
static double f_comma(const double *a)
{
	double x = a[0], y = a[1], z = a[2], s = a[3];
	if (x == 0 && z == 0)
		x = 0.0001;
	double ball = sqrt(sq(x - 0.5 * s) + y * y + z * z) - 0.5 * s;
	double r = 0.5 * s * cos(atan2(fabs(z), x) / 2);
	double core = sqrt(sq(x + 0.25 * s) + z * z) - 0.75 * s;
	double tail = sqrt(core * core + y * y) - r;
	return fmin(ball, fmax(tail, -z));
}

/* ---- noise ----
 * POV-Ray's internal noise functions are its solid noise, the one its bozo
 * pattern gives (measured: f_noise3d equals bozo with noise_generator 2 and
 * f_noise_generator(x, y, z, G) bozo with generator G at every point), so
 * they call the patterns' noise3. */

/* Noise in [0, 1] by generator: 1 is POV-Ray's original generator, whose
 * values often clip at 0 and 1; 2 (the default) is range corrected; 3 is
 * Perlin's. The generator number is taken modulo 4 and 0 acts as 1, as in
 * POV-Ray. NaN where a coordinate is not finite. */
static double noise_gen(double x, double y, double z, int gen)
{
	if (!isfinite(x) || !isfinite(y) || !isfinite(z))
		return NAN;
	int g = (int)((unsigned)gen & 3u);
	return noise3(v3(x, y, z), g == 0 ? 1 : g);
}

static double f_noise3d(const double *a)
{
	return noise_gen(a[0], a[1], a[2], 2);
}

static double f_noise_generator(const double *a)
{
	return noise_gen(a[0], a[1], a[2], to_int(a[3], 1 << 20));
}

/* Noise in about [-1, 1] for the fractal sums. */
static double snoise(double x, double y, double z, int gen)
{
	return 2 * noise_gen(x, y, z, gen) - 1;
}

/* Musgrave's heterogeneous multifractal: P0 H, P1 lacunarity, P2 octaves,
 * P3 offset, P4 T, P5 the noise generator. The value starts at offset +
 * snoise(p); each further octave i (while i < octaves) adds
 * (snoise(lac^i p) + offset) lac^(-iH) w, where w is the value so far
 * raised to the whole part of T (1 when that is 0 or less); a fractional
 * part r of octaves adds r times the next octave's term times the value so
 * far. Measured against POV-Ray 3.7 (Musgrave's published form). */
static double f_hetero_mf(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double H = a[3], lac = a[4], oct = a[5], off = a[6];
	int T = to_int(a[7], 64);
	int gen = to_int(a[8], 1 << 20);
	double limit = oct < 64 ? oct : 64;
	double freq = 1, v = off + snoise(x, y, z, gen);
	int i;
	for (i = 1; i < limit; i++) {
		freq *= lac;
		x *= lac;
		y *= lac;
		z *= lac;
		double weight = T > 0 ? pow(v, T) : 1;
		v += (snoise(x, y, z, gen) + off) * pow(freq, -H) * weight;
	}
	double rem = limit - x86_int(limit);
	if (rem > 0) {
		freq *= lac;
		x *= lac;
		y *= lac;
		z *= lac;
		v += rem * (snoise(x, y, z, gen) + off) * pow(freq, -H) * v;
	}
	return v;
}

/* Ridged noise: P0 lambda (the lacunarity), P1 octaves, P2 omega (the
 * gain of each octave), P3 offset, P4 ridge, P5 generator. Measured
 * against POV-Ray 3.7 (one octave, then several, over offsets, ridges and
 * fractional octaves; to 1e-10):
 *   - each octave's noise n is folded at the ridge r into a tent,
 *     t = 1 - |n - r| / max(r, 1 - r) (a ridge of 1 or more leaves n / r);
 *   - the offset o maps t linearly: 1 - t / (1 - o) for o up to 0.5,
 *     (1 - t) / o - 1 above;
 *   - the octaves are averaged with weights omega^i; the first always
 *     counts in full, and a fractional part f of the octaves gives the
 *     octave after the whole ones (after the first, below 1) weight
 *     f omega^i, negative octaves included (f < 0 there). */
static double ridge_octave(double n, double off, double r)
{
	double t = 1 - fabs(n - r) / fmax(r, 1 - r);
	return off <= 0.5 ? 1 - t / (1 - off) : (1 - t) / off - 1;
}

static double f_ridge(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double lambda = a[3], oct = a[4], omega = a[5], off = a[6], r = a[7];
	int gen = to_int(a[8], 1 << 20);
	double limit = oct < 64 ? oct : 64;
	int whole = limit >= 1 ? (int)limit : 1;
	double frac = limit - x86_int(limit);
	double v = 0, total = 0, amp = 1;
	for (int i = 0; i <= whole; i++) {
		double w = i < whole ? amp : frac * amp;
		if (w != 0) {
			v += w * ridge_octave(noise_gen(x, y, z, gen), off, r);
			total += w;
		}
		amp *= omega;
		x *= lambda;
		y *= lambda;
		z *= lambda;
	}
	return total != 0 ? v / total : v;
}

/* Musgrave's ridged multifractal: P0 H, P1 lacunarity, P2 octaves, P3
 * offset, P4 gain, P5 generator. Octave i (from 0) counts while i <
 * octaves, so a fractional count rounds up (measured: 2.5 octaves give
 * the value of 3, 0.5 that of 1).
 *
 * POV-Ray 3.7 computes the octaves' weights lac^(-iH) once, at the first
 * call of f_ridged_mf in a run, for that call's H, lacunarity and octave
 * count, and reuses them in every later call (measured: after a first call
 * with H 0.2 and lacunarity 2.5, a call with 0.5 and 2 weighs its second
 * octave by 2.5^-0.2; weights beyond the first call's count read zero or
 * garbage). lucent computes them for each call, which is POV-Ray's value
 * wherever the scene calls it with one H and lacunarity and no more
 * octaves than its first call has (tests/lang/stdlib-functions-ridged). */
static double f_ridged_mf(const double *a)
{
	double x = a[0], y = a[1], z = a[2];
	double H = a[3], lac = a[4], oct = a[5], off = a[6], gain = a[7];
	int gen = to_int(a[8], 1 << 20);
	double sig = sq(off - fabs(snoise(x, y, z, gen)));
	double v = sig, freq = 1;
	for (int i = 1; i < oct && i < 64; i++) {
		x *= lac;
		y *= lac;
		z *= lac;
		freq *= lac;
		double w = sig * gain;
		w = w > 1 ? 1 : w < 0 ? 0 : w;
		sig = sq(off - fabs(snoise(x, y, z, gen))) * w;
		v += sig * pow(freq, -H);
	}
	return v;
}

/* Internal function 77 has no name in functions.inc and returns 0 for any
 * point. */
static double f_zero(const double *a)
{
	(void)a;
	return 0;
}

/* ---- the table, in POV-Ray's numbering ---- */

struct internal_def {
	const char *name;    /* functions.inc's name, for the reader */
	int nparams;         /* x, y, z and the extra parameters */
	double (*eval)(const double *args);
};

static const struct internal_def internal_defs[] = {
	{"f_algbr_cyl1", 8, f_algbr_cyl1},
	{"f_algbr_cyl2", 8, f_algbr_cyl2},
	{"f_algbr_cyl3", 8, f_algbr_cyl3},
	{"f_algbr_cyl4", 8, f_algbr_cyl4},
	{"f_bicorn", 5, f_bicorn},
	{"f_bifolia", 5, f_bifolia},
	{"f_blob", 8, f_blob},
	{"f_blob2", 7, f_blob2},
	{"f_boy_surface", 5, f_boy_surface},
	{"f_comma", 4, f_comma},
	{"f_cross_ellipsoids", 7, f_cross_ellipsoids},        /* 10 */
	{"f_crossed_trough", 4, f_crossed_trough},
	{"f_cubic_saddle", 4, f_cubic_saddle},
	{"f_cushion", 4, f_cushion},
	{"f_devils_curve", 4, f_devils_curve},
	{"f_devils_curve_2d", 9, f_devils_curve_2d},
	{"f_dupin_cyclid", 9, f_dupin_cyclid},
	{"f_ellipsoid", 6, f_ellipsoid},
	{"f_enneper", 4, f_enneper},
	{"f_flange_cover", 7, f_flange_cover},
	{"f_folium_surface", 6, f_folium_surface},            /* 20 */
	{"f_folium_surface_2d", 9, f_folium_surface_2d},
	{"f_glob", 4, f_glob},
	{"f_heart", 4, f_heart},
	{"f_helical_torus", 13, f_helical_torus},
	{"f_helix1", 10, f_helix1},
	{"f_helix2", 10, f_helix2},
	{"f_hex_x", 4, f_hex_x},
	{"f_hex_y", 4, f_hex_y},
	{"f_hetero_mf", 9, f_hetero_mf},
	{"f_hunt_surface", 4, f_hunt_surface},                /* 30 */
	{"f_hyperbolic_torus", 6, f_hyperbolic_torus},
	{"f_isect_ellipsoids", 7, f_isect_ellipsoids},
	{"f_kampyle_of_eudoxus", 6, f_kampyle_of_eudoxus},
	{"f_kampyle_of_eudoxus_2d", 9, f_kampyle_of_eudoxus_2d},
	{"f_klein_bottle", 4, f_klein_bottle},
	{"f_kummer_surface_v1", 4, f_kummer_surface_v1},
	{"f_kummer_surface_v2", 7, f_kummer_surface_v2},
	{"f_lemniscate_of_gerono", 4, f_lemniscate_of_gerono},
	{"f_lemniscate_of_gerono_2d", 9, f_lemniscate_of_gerono_2d},
	{"f_mesh1", 8, f_mesh1},                              /* 40 */
	{"f_mitre", 4, f_mitre},
	{"f_nodal_cubic", 4, f_nodal_cubic},
	{"f_odd", 4, f_cushion},
	{"f_ovals_of_cassini", 7, f_ovals_of_cassini},
	{"f_paraboloid", 4, f_paraboloid},
	{"f_parabolic_torus", 6, f_parabolic_torus},
	{"f_ph", 3, f_ph},
	{"f_pillow", 4, f_pillow},
	{"f_piriform", 4, f_piriform},
	{"f_piriform_2d", 10, f_piriform_2d},                 /* 50 */
	{"f_poly4", 8, f_poly4},
	{"f_polytubes", 9, f_polytubes},
	{"f_quantum", 4, f_quantum},
	{"f_quartic_paraboloid", 4, f_quartic_paraboloid},
	{"f_quartic_saddle", 4, f_quartic_saddle},
	{"f_quartic_cylinder", 6, f_quartic_cylinder},
	{"f_r", 3, f_r},
	{"f_ridge", 9, f_ridge},
	{"f_ridged_mf", 9, f_ridged_mf},
	{"f_rounded_box", 7, f_rounded_box},                  /* 60 */
	{"f_sphere", 4, f_sphere},
	{"f_spikes", 8, f_spikes},
	{"f_spikes_2d", 7, f_spikes_2d},
	{"f_spiral", 9, f_spiral},
	{"f_steiners_roman", 4, f_steiners_roman},
	{"f_strophoid", 7, f_strophoid},
	{"f_strophoid_2d", 10, f_strophoid_2d},
	{"f_superellipsoid", 5, f_superellipsoid},
	{"f_th", 3, f_th},
	{"f_torus", 5, f_torus},                              /* 70 */
	{"f_torus2", 6, f_torus2},
	{"f_torus_gumdrop", 4, f_torus_gumdrop},
	{"f_umbrella", 4, f_umbrella},
	{"f_witch_of_agnesi", 5, f_witch_of_agnesi},
	{"f_witch_of_agnesi_2d", 9, f_witch_of_agnesi_2d},
	{"f_noise3d", 3, f_noise3d},
	{"(none)", 3, f_zero},
	{"f_noise_generator", 4, f_noise_generator},
};

enum { INTERNAL_COUNT = sizeof internal_defs / sizeof internal_defs[0] };

double fn_internal(int n, const double *args, int nargs)
{
	if (n < 0 || n >= INTERNAL_COUNT || nargs < internal_defs[n].nparams)
		return NAN;
	return internal_defs[n].eval(args);
}

int fn_internal_params(int n)
{
	if (n < 0 || n >= INTERNAL_COUNT)
		return -1;
	return internal_defs[n].nparams;
}

/* spline2.h: the plane curves of prism and lathe, one piece at a time.
 * A piece is a pair of polynomials in u on [0, 1] of degree 1 to 3,
 * c[0] + c[1] u + c[2] u^2 + c[3] u^3, one per coordinate. The four
 * splines are POV-Ray's (measured with trace() to eight digits):
 * - linear: the straight line from P[0] to P[1];
 * - quadratic: the parabola through P[0], P[1], P[2] at u = -1, 0, 1,
 *   drawn from P[1] to P[2] (P[0] only steers);
 * - cubic: Catmull-Rom, the Hermite cubic from P[1] to P[2] with tangents
 *   (P[2] - P[0]) / 2 and (P[3] - P[1]) / 2;
 * - bezier: the cubic Bezier curve of the four points. */
#ifndef LUCENT_GEOM_SPLINE2_H
#define LUCENT_GEOM_SPLINE2_H

/* The same order as enum prism_spline and enum lathe_spline. */
enum spline2_kind { SPLINE2_LINEAR, SPLINE2_QUADRATIC, SPLINE2_CUBIC, SPLINE2_BEZIER };

/* The piece of the spline `kind` whose control points start at p (2, 3, 4
 * or 4 points): its coefficients for the first coordinate in c0 and the
 * second in c1 (4 each, unused ones 0), and its extent on each coordinate
 * in lo and hi (for bezier the control points', as POV-Ray bounds it).
 * Returns the degree. */
int spline2_piece(enum spline2_kind kind, const double (*p)[2], double c0[4], double c1[4], double lo[2],
                  double hi[2]);

/* A piece's coordinate and its derivative at u. */
static inline double spline2_at(const double c[4], double u)
{
	return ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
}

static inline double spline2_slope(const double c[4], double u)
{
	return (3 * c[3] * u + 2 * c[2]) * u + c[1];
}

#endif

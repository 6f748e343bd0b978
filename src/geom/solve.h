/* solve.h: real roots of polynomials, computed without catastrophic
 * cancellation: closed forms for degrees 2 to 4 with every root polished by
 * Newton steps on the original polynomial, and a Sturm-sequence solver for
 * degrees up to SOLVE_MAX_DEGREE that the closed forms fall back on where
 * rounding leaves the number of real roots undecided.
 *
 * Conventions shared by every solver but solve_quadratic:
 * - c[i] is the coefficient of t^i (ascending powers), so a cubic is
 *   c[3] t^3 + c[2] t^2 + c[1] t + c[0].
 * - Leading coefficients that are exactly zero lower the degree.
 * - Roots are written in ascending order and are distinct: a multiple root
 *   (a tangent ray) is reported once.
 * - A polynomial with a non-finite coefficient, or the zero polynomial,
 *   has no roots; no root returned is ever NaN or infinite. */
#ifndef LUCENT_SOLVE_H
#define LUCENT_SOLVE_H

#include <stdbool.h>

#define SOLVE_MAX_DEGREE 7

/* Narrow the span [*lo, *hi] a solver searches to the part between a and
 * b (in either order); false if nothing is left. */
static inline bool span_narrow(double a, double b, double *lo, double *hi)
{
	if (a > b) {
		double t = a;
		a = b;
		b = t;
	}
	if (a > *lo)
		*lo = a;
	if (b < *hi)
		*hi = b;
	return *lo <= *hi;
}

/* Real roots of a t^2 + b t + c = 0, ascending, into r[0..1]; returns the
 * count (0, 1 for a double root or a linear equation, or 2). */
int solve_quadratic(double a, double b, double c, double r[2]);

/* All real roots of c[3] t^3 + c[2] t^2 + c[1] t + c[0]; returns how many
 * (at most 3) written to r. */
int solve_cubic(const double c[4], double r[3]);

/* All real roots of c[4] t^4 + ... + c[0]; returns how many (at most 4).
 * Ferrari's factorisation into two quadratics, refined by Newton's method
 * on the factors until it is backward stable; where a near-double root
 * makes the count of real roots uncertain, the Sturm solver decides. */
int solve_quartic(const double c[5], double r[4]);

/* The real roots t with tmin < t < tmax of the polynomial of the given
 * degree (0..SOLVE_MAX_DEGREE; c has degree+1 entries, c[i] multiplying
 * t^i); returns how many were written to roots (room for `degree` needed).
 * tmin and tmax may be infinite. Degrees up to 4 use the closed forms
 * unless `sturm` is set; higher degrees, `sturm`, and closed-form results
 * in doubt use Sturm sequences: roots are counted by sign changes, isolated
 * by bisection and refined by safeguarded Newton/bisection. Returns 0 for a
 * degree outside the range. No allocation. */
int solve_poly(const double *c, int degree, double tmin, double tmax, bool sturm, double *roots);

#endif

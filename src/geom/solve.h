/* solve.h: polynomial roots, computed without catastrophic cancellation. */
#ifndef LUCENT_SOLVE_H
#define LUCENT_SOLVE_H

/* Real roots of a t^2 + b t + c = 0, ascending, into r[0..1]; returns the
 * count (0, 1 for a double root or a linear equation, or 2). */
int solve_quadratic(double a, double b, double c, double r[2]);

#endif

/* solve.c: polynomial root solvers (see solve.h). */
#include "geom/solve.h"

#include <math.h>

int solve_quadratic(double a, double b, double c, double r[2])
{
	if (a == 0) {
		if (b == 0)
			return 0;
		r[0] = -c / b;
		return 1;
	}
	double disc = b * b - 4 * a * c;
	if (disc < 0)
		return 0;
	if (disc == 0) {
		r[0] = -b / (2 * a);
		return 1;
	}
	/* q has the sign of b, so -b and the root never cancel. */
	double q = -0.5 * (b + copysign(sqrt(disc), b));
	double t0 = q / a, t1 = q != 0 ? c / q : -t0;
	if (t0 > t1) {
		double tmp = t0;
		t0 = t1;
		t1 = tmp;
	}
	r[0] = t0;
	r[1] = t1;
	return 2;
}

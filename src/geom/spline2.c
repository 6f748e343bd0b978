/* spline2.c: the pieces of prism's and lathe's plane curves (spline2.h). */
#include "geom/spline2.h"
#include "geom/solve.h"

#include <math.h>
#include <string.h>

/* The extent of c(u) for u in [0, 1]: the ends and where the derivative
 * vanishes. */
static void extent(const double c[4], double *lo, double *hi)
{
	double a = spline2_at(c, 0), b = spline2_at(c, 1);
	*lo = fmin(a, b);
	*hi = fmax(a, b);
	double r[2];
	int n = solve_quadratic(3 * c[3], 2 * c[2], c[1], r);
	for (int i = 0; i < n; i++)
		if (r[i] > 0 && r[i] < 1) {
			double v = spline2_at(c, r[i]);
			*lo = fmin(*lo, v);
			*hi = fmax(*hi, v);
		}
}

int spline2_piece(enum spline2_kind kind, const double (*p)[2], double c0[4], double c1[4], double lo[2],
                  double hi[2])
{
	int deg = 1;
	for (int k = 0; k < 2; k++) {
		double *c = k == 0 ? c0 : c1;
		memset(c, 0, 4 * sizeof *c);
		switch (kind) {
		case SPLINE2_LINEAR:
			c[0] = p[0][k];
			c[1] = p[1][k] - p[0][k];
			deg = 1;
			break;
		case SPLINE2_QUADRATIC:
			c[0] = p[1][k];
			c[1] = (p[2][k] - p[0][k]) / 2;
			c[2] = (p[2][k] + p[0][k]) / 2 - p[1][k];
			deg = 2;
			break;
		case SPLINE2_CUBIC: {
			double m1 = (p[2][k] - p[0][k]) / 2, m2 = (p[3][k] - p[1][k]) / 2;
			c[0] = p[1][k];
			c[1] = m1;
			c[2] = 3 * (p[2][k] - p[1][k]) - 2 * m1 - m2;
			c[3] = 2 * (p[1][k] - p[2][k]) + m1 + m2;
			deg = 3;
			break;
		}
		case SPLINE2_BEZIER:
			c[0] = p[0][k];
			c[1] = 3 * (p[1][k] - p[0][k]);
			c[2] = 3 * (p[0][k] - 2 * p[1][k] + p[2][k]);
			c[3] = p[3][k] - p[0][k] + 3 * (p[1][k] - p[2][k]);
			deg = 3;
			break;
		}
		if (kind == SPLINE2_BEZIER) {
			lo[k] = hi[k] = p[0][k];
			for (int i = 1; i < 4; i++) {
				lo[k] = fmin(lo[k], p[i][k]);
				hi[k] = fmax(hi[k], p[i][k]);
			}
		} else {
			extent(c, &lo[k], &hi[k]);
		}
	}
	return deg;
}

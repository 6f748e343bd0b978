/* tiling.c: the tiling pattern (see kinds.h; pavement is in pavement.c).
 *
 * tiling N: one of POV-Ray's 27 periodic tilings of the x-z plane (y is
 * ignored). At a point of a tile of type t (of the tiling's N types) the
 * value is (t + 1 - min(1, d/rho))/N, d the distance from the tile's
 * nearest edge and rho the bevel width (the smallest inradius among the
 * tiling's tiles; a few edges have their own): each type keeps its band
 * of a map, its edges at (t+1)/N and, beyond the bevel, its face at t/N,
 * as the manual describes. The geometry is measured (tiling_gen.py). */
#include "pattern/kinds.h"
#include "pattern/tiling_table.h"

#include <math.h>
#include <stddef.h>

/* The value of tiling def at (x, z): the tile that holds the point is the
 * one the point is deepest inside (the largest least distance from its
 * edges) among the cell's polygons and their copies in the eight
 * neighbouring cells. */
static double tiling_at(const struct tiling_def *def, double x, double z)
{
	double u = floor(def->inv[0] * x + def->inv[1] * z);
	double w = floor(def->inv[2] * x + def->inv[3] * z);
	double x0 = x - u * def->a[0] - w * def->b[0];
	double z0 = z - u * def->a[1] - w * def->b[1];
	double best = -INFINITY;
	const struct tile_poly *in = NULL;
	double px_in = 0, pz_in = 0;
	for (int i = -1; i <= 1; i++) {
		for (int j = -1; j <= 1; j++) {
			double px = x0 - i * def->a[0] - j * def->b[0];
			double pz = z0 - i * def->a[1] - j * def->b[1];
			for (int k = 0; k < def->npoly; k++) {
				const struct tile_poly *poly = &def->poly[k];
				const struct tile_edge *e = &def->edge[poly->first];
				double d = INFINITY;
				for (int m = 0; m < poly->count && d > best; m++) {
					double dm = e[m].off - (e[m].nx * px + e[m].nz * pz);
					if (dm < d)
						d = dm;
				}
				if (d > best) {
					best = d;
					in = poly;
					px_in = px;
					pz_in = pz;
				}
			}
		}
	}
	if (!in)
		return 0;
	const struct tile_edge *e = &def->edge[in->first];
	double r = 1.0;
	for (int m = 0; m < in->count; m++) {
		double rm = (e[m].off - (e[m].nx * px_in + e[m].nz * pz_in)) * e[m].inv_rho;
		if (rm < r)
			r = rm;
	}
	if (r < 0)
		r = 0;
	return (in->type + 1 - r) / def->ntypes;
}

PATTERN_FN(tiling)
{
	(void)ctx;
	int n = pt->n[0];
	if (n < 1 || n > TILING_COUNT || tiling_defs[n - 1].ntypes == 0)
		return 0;
	return tiling_at(&tiling_defs[n - 1], q.x, q.z);
}

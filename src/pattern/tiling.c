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
#include <stdbool.h>
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

/* ---- tiling 27: Penrose's rhombi ----
 *
 * Measured: POV-Ray's tiling 27 is the Penrose rhombus tiling with unit
 * edges along the directions e_j = (cos 72j, sin 72j) (x, z) and a vertex
 * at the origin; every vertex is sum K_j e_j with integer K_j, and the
 * vertex set is the cut-and-project one with no shift in perpendicular
 * space, five-fold symmetric about the origin (fitted to 17 628 vertices in
 * [-60, 60]^2). That is de Bruijn's pentagrid construction with every
 * gamma_j = -1/5: the grid lines x . e_j + gamma_j = k, and for each
 * crossing of lines of families r and s the rhombus
 * sum_j K_j e_j + a e_r + b e_s, 0 <= a, b <= 1, K_j = ceil(x . e_j + gamma_j)
 * at the crossing for the other j. Thick rhombi (72 degrees, e_r and e_s
 * 72 degrees apart) are type 0, thin ones type 1; the bevel width is 0.2915377
 * (measured; the thin rhombus's inradius would be 0.2938926). */

#define PENROSE_GAMMA (-0.2)
#define PENROSE_BEVEL 0.2915377

static const double pen_e[5][2] = {
	{1, 0}, {0.30901699437494745, 0.95105651629515353}, {-0.80901699437494734, 0.58778525229247325},
	{-0.80901699437494756, -0.58778525229247303}, {0.30901699437494723, -0.95105651629515364}};

/* A rhombus of the tiling: the crossing of families r < s at vertex v; the
 * point's coordinates (u, w) along e_r and e_s inside it. */
struct rhomb {
	int r, s;
	double vx, vz;
	double u, w;
};

static bool rhomb_thick(const struct rhomb *t)
{
	return (t->s - t->r) % 5 == 1 || (t->s - t->r) % 5 == 4;
}

/* The rhombus of the crossing (r, kr) x (s, ks) if it holds (x, z). */
static bool penrose_crossing(int r, int s, double kr, double ks, double x, double z, struct rhomb *t)
{
	const double *er = pen_e[r], *es = pen_e[s];
	double det = er[0] * es[1] - er[1] * es[0];
	double a = kr - PENROSE_GAMMA, b = ks - PENROSE_GAMMA;
	double gx = (a * es[1] - b * er[1]) / det, gz = (-a * es[0] + b * er[0]) / det;
	double vx = kr * er[0] + ks * es[0], vz = kr * er[1] + ks * es[1];
	for (int j = 0; j < 5; j++) {
		if (j == r || j == s)
			continue;
		double k = ceil(gx * pen_e[j][0] + gz * pen_e[j][1] + PENROSE_GAMMA);
		vx += k * pen_e[j][0];
		vz += k * pen_e[j][1];
	}
	double dx = x - vx, dz = z - vz;
	double u = (dx * es[1] - dz * es[0]) / det, w = (-dx * er[1] + dz * er[0]) / det;
	if (u < 0 || u >= 1 || w < 0 || w >= 1)
		return false;
	*t = (struct rhomb){r, s, vx, vz, u, w};
	return true;
}

/* The rhombus that holds (x, z). */
static void penrose_find(double x, double z, struct rhomb *t)
{
	/* The tiling point p comes from about the grid point 2p/5: the crossings
	 * next to it hold the rhombus (always those just above and below in
	 * every family at 20 000 random points; a wider search is the fallback). */
	double gx = 0.4 * x, gz = 0.4 * z;
	for (int reach = 0; reach <= 3; reach += 3)
		for (int r = 0; r < 5; r++)
			for (int s = r + 1; s < 5; s++) {
				double br = floor(gx * pen_e[r][0] + gz * pen_e[r][1] + PENROSE_GAMMA);
				double bs = floor(gx * pen_e[s][0] + gz * pen_e[s][1] + PENROSE_GAMMA);
				for (double kr = br - reach; kr <= br + 1 + reach; kr++)
					for (double ks = bs - reach; ks <= bs + 1 + reach; ks++)
						if (penrose_crossing(r, s, kr, ks, x, z, t))
							return;
			}
	*t = (struct rhomb){0, 1, x, z, 0.5, 0.5};  /* not reached */
}

static double penrose_rhombi(double x, double z)
{
	struct rhomb t;
	penrose_find(x, z, &t);
	double sine = fabs(pen_e[t.r][0] * pen_e[t.s][1] - pen_e[t.r][1] * pen_e[t.s][0]);
	double d = fmin(fmin(t.u, 1 - t.u), fmin(t.w, 1 - t.w)) * sine;
	return ((rhomb_thick(&t) ? 0 : 1) + 1 - fmin(1, d / PENROSE_BEVEL)) / 2;
}

/* ---- tiling 26: Penrose's kites and darts ----
 *
 * Measured: POV-Ray's tiling 26 is made of the Robinson triangles of the
 * rhombus tiling above scaled by 1/phi: every rhombus cut along its
 * diagonal V-C (the long one of a thick rhombus, the short one of a thin
 * one) gives two triangles, acute (36, 72, 72 degrees) from thin rhombi and
 * obtuse (108, 36, 36) from thick ones. An acute triangle and the obtuse one
 * across its side whose end at the acute triangle's 72-degree corner is the
 * obtuse triangle's 108-degree corner make half a kite; the other obtuse
 * triangles pair, across the side at whose end both have their 108-degree
 * corner, into darts. Kites are type 0, darts type 1; the bevel is measured
 * from the tile's outer edges (not the seams), 0.2242152 wide. At 8 000
 * random points every type agrees with POV-Ray's, and every value. */

#define PENROSE_KITE_SCALE 0.61803398874989485   /* 1/phi */
#define PENROSE_KITE_BEVEL 0.2242152

struct pt2 {
	double x, z;
};

/* A Robinson triangle: the corner off the rhombus's diagonal (apex) and the
 * diagonal's ends (b0 = V, b1 = C), and whether it is obtuse (from a thick
 * rhombus). */
struct robinson {
	struct pt2 apex, b0, b1;
	bool obtuse;
};

static struct robinson robinson_at(double x, double z)
{
	struct rhomb t;
	penrose_find(x, z, &t);
	const double *er = pen_e[t.r], *es = pen_e[t.s];
	struct robinson h;
	h.b0 = (struct pt2){t.vx, t.vz};
	h.b1 = (struct pt2){t.vx + er[0] + es[0], t.vz + er[1] + es[1]};
	h.apex = t.u > t.w ? (struct pt2){t.vx + er[0], t.vz + er[1]} : (struct pt2){t.vx + es[0], t.vz + es[1]};
	h.obtuse = rhomb_thick(&t);
	return h;
}

static bool same_pt(struct pt2 a, struct pt2 b)
{
	return fabs(a.x - b.x) < 1e-6 && fabs(a.z - b.z) < 1e-6;
}

/* The Robinson triangle across side a-b of triangle h. */
static struct robinson robinson_across(const struct robinson *h, struct pt2 a, struct pt2 b)
{
	double cx = (h->apex.x + h->b0.x + h->b1.x) / 3, cz = (h->apex.z + h->b0.z + h->b1.z) / 3;
	double mx = (a.x + b.x) / 2, mz = (a.z + b.z) / 2;
	return robinson_at(mx + (mx - cx) * 0.02, mz + (mz - cz) * 0.02);
}

/* An obtuse triangle's kite partner: the acute triangle across one of its
 * sides from the apex, whose rhombus has its obtuse corner at that apex
 * (the ends of a thin rhombus's short diagonal). */
static bool kite_partner(const struct robinson *h, struct robinson *acute, struct pt2 *far)
{
	for (int k = 0; k < 2; k++) {
		struct pt2 end = k ? h->b1 : h->b0;
		struct robinson n = robinson_across(h, h->apex, end);
		if (!n.obtuse && (same_pt(n.b0, h->apex) || same_pt(n.b1, h->apex))) {
			*acute = n;
			*far = k ? h->b0 : h->b1;
			return true;
		}
	}
	return false;
}

/* The distance from line a-b. */
static double line_dist(struct pt2 p, struct pt2 a, struct pt2 b)
{
	double dx = b.x - a.x, dz = b.z - a.z;
	return fabs((p.x - a.x) * dz - (p.z - a.z) * dx) / hypot(dx, dz);
}

static double penrose_kites(double x, double z)
{
	struct pt2 p = {x / PENROSE_KITE_SCALE, z / PENROSE_KITE_SCALE};
	struct robinson h = robinson_at(p.x, p.z);
	double d = INFINITY;
	int type = 0;
	if (!h.obtuse) {
		/* half a kite: this acute triangle and its obtuse partner */
		for (int k = 0; k < 2 && isinf(d); k++) {
			struct pt2 q = k ? h.b1 : h.b0, other = k ? h.b0 : h.b1;
			struct robinson n = robinson_across(&h, h.apex, q);
			if (n.obtuse && same_pt(n.apex, q)) {
				struct pt2 r = same_pt(n.b0, h.apex) ? n.b1 : n.b0;
				d = fmin(line_dist(p, h.apex, r), line_dist(p, h.apex, other));
			}
		}
	} else {
		struct robinson a;
		struct pt2 r;
		if (kite_partner(&h, &a, &r)) {
			struct pt2 other = same_pt(a.b0, h.apex) ? a.b1 : a.b0;
			d = fmin(line_dist(p, a.apex, r), line_dist(p, a.apex, other));
		} else {
			/* half a dart: the seam is the side whose neighbour is
			 * another dart's half with the same apex */
			type = 1;
			for (int k = 0; k < 2 && isinf(d); k++) {
				struct pt2 end = k ? h.b1 : h.b0, other = k ? h.b0 : h.b1;
				struct robinson n = robinson_across(&h, h.apex, end);
				struct robinson a2;
				struct pt2 r2;
				if (n.obtuse && same_pt(n.apex, h.apex) && !kite_partner(&n, &a2, &r2))
					d = fmin(line_dist(p, h.apex, other), line_dist(p, h.b0, h.b1));
			}
		}
	}
	if (isinf(d))
		d = 0;
	return (type + 1 - fmin(1, d * PENROSE_KITE_SCALE / PENROSE_KITE_BEVEL)) / 2;
}

PATTERN_FN(tiling)
{
	(void)ctx;
	int n = pt->n[0];
	if (n == 27)
		return penrose_rhombi(q.x, q.z);
	if (n == 26)
		return penrose_kites(q.x, q.z);
	if (n < 1 || n > TILING_COUNT || tiling_defs[n - 1].ntypes == 0)
		return 0;
	return tiling_at(&tiling_defs[n - 1], q.x, q.z);
}

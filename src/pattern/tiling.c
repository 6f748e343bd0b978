/* tiling.c: the tiling pattern (see kinds.h; pavement is in pavement.c).
 *
 * tiling N: one of POV-Ray's 27 tilings of the x-z plane (y is ignored);
 * 1 to 24 are periodic, 25 to 27 Penrose's, built below. At a point of a
 * tile of type t (of the tiling's N types) the value is (t + 1 - min(1, d/rho))/N, d the distance from the tile's
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

/* The value of a Penrose tiling's tile of type t (of n) at r = the
 * distance from its edge over the bevel width: (t + 1 - r)/n as for the
 * other tilings, r at most 1, but measured to stay 1e-6 inside the type's
 * band [t/n, (t+1)/n]: 1e-6 below (t+1)/n on and near the edges, 1e-6
 * above t/n on the flat face beyond the bevel (except for type 0, whose
 * face is 0). So a colour map entry at exactly t/n colours the face with
 * the entry after it and the edge with the one before. */
static double penrose_value(int t, int n, double r)
{
	double v = (t + 1 - fmin(r, 1)) / n;
	v = fmin(v, (double)(t + 1) / n - 1e-6);
	if (t > 0)
		v = fmax(v, (double)t / n + 1e-6);
	return v;
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
				/* whole offsets: past 2^53 br + 1 is br */
				for (int a = -reach; a <= 1 + reach; a++)
					for (int b = -reach; b <= 1 + reach; b++)
						if (penrose_crossing(r, s, br + a, bs + b, x, z, t))
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
	return penrose_value(rhomb_thick(&t) ? 0 : 1, 2, d / PENROSE_BEVEL);
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
	return penrose_value(type, 2, d * PENROSE_KITE_SCALE / PENROSE_KITE_BEVEL);
}

/* ---- tiling 25: Penrose's pentagons, stars, boats and diamonds ----
 *
 * Measured (POV-Ray's values on a 400 x 400 grid over [-8, 8]^2, and at
 * 98 831 lattice points out to 220 units): POV-Ray's tiling 25 is
 * Penrose's first tiling (P1) with unit edges, a decoration of the rhombus
 * tiling of de Bruijn's pentagrid with every offset gamma = -2/5 and edge
 * L = 1/tan 36 degrees (twice the pentagon's apothem). Its vertices are the
 * points L sum K_j e_j whose perpendicular image q = sum K_j f_j
 * (f_j = (cos 144j, sin 144j)) lies in the window of their class
 * sum K_j mod 5: for classes 0 and 1 a pentagon of circumradius phi, for
 * 2 and 4 one of circumradius 1 (class 3 is empty), with corners at
 * 36 + 72k degrees for classes 0 and 2, at 72k for 1 and 4.
 *
 * A vertex of class 0 or 1 is the centre of a pentagon of the tiling
 * (corners towards 36 + 72k degrees for class 0, 72k for class 1). Every
 * other tile is bounded by pentagons only and holds one vertex of class 2
 * or 4. The window's diagonals (its pentagram) split it into the inner
 * pentagon, the five points of the star and the five triangles outside
 * the star, telling where q is (0, 1 or 2 diagonals crossed) the kind of
 * tile: for pentagon vertices types 0, 2 and 1 (POV-Ray's three kinds of
 * pentagon), for the others a star (type 3) around the vertex, a boat
 * (type 4, a star cut by a straight edge 0.16 from the vertex) or a
 * diamond (type 5, a thin rhombus holding the vertex off its centre).
 *
 * The bevel is 0.2915377 wide, as tiling 27's. In pentagons and diamonds
 * the distance is the one from the tile's edges; in stars and boats it is
 * the distance from the line of the edge that the ray from the vertex
 * through the point meets (smaller than the distance from the tile near
 * its concave corners), or the distance from the tile where that is
 * smaller. Every one of the grid's 160 000 values matches. */

#define P1_SCALE 1.3763819204711736    /* L = 1/tan 36: the rhombi's edge */
#define P1_APOTHEM 0.6881909602355868  /* of the unit pentagon */
#define P1_CIRCUM 0.85065080835203993  /* the unit pentagon's circumradius */
#define P1_PHI 1.6180339887498949
#define P1_MAXV 64

static const double pen_f[5][2] = {
	{1, 0}, {-0.80901699437494734, 0.58778525229247325}, {0.30901699437494723, -0.95105651629515364},
	{0.30901699437494745, 0.95105651629515353}, {-0.80901699437494756, -0.58778525229247303}};

/* unit vectors at 36 + 72k degrees (classes 0 and 2) and 72k (1 and 4) */
static const double p1_dir[2][5][2] = {
	{{0.80901699437494745, 0.58778525229247314}, {-0.30901699437494734, 0.95105651629515364},
	 {-1, 0}, {-0.30901699437494756, -0.95105651629515353}, {0.80901699437494734, -0.58778525229247325}},
	{{1, 0}, {0.30901699437494745, 0.95105651629515353}, {-0.80901699437494734, 0.58778525229247325},
	 {-0.80901699437494756, -0.58778525229247303}, {0.30901699437494723, -0.95105651629515364}}};

/* A vertex of the decorated tiling: its centre in space, its class's
 * orientation (0: corners at 36 + 72k degrees) and its window region. */
struct p1_vertex {
	double x, z;
	int orient, region;
};

/* The region of q in class c's window: 0, 1 or 2 diagonals crossed, or -1
 * outside the window. */
static int p1_region(int c, double qx, double qz)
{
	double r = c < 2 ? P1_PHI : 1.0;
	const double (*u)[2] = p1_dir[c == 1 || c == 4];
	int crossed = 0;
	for (int k = 0; k < 5; k++) {
		double s = qx * u[k][0] + qz * u[k][1];
		if (-s > r * 0.80901699437494745)   /* beyond the edge facing -u_k */
			return -1;
		if (s > r * 0.30901699437494745)    /* beyond the diagonal across u_k */
			crossed++;
	}
	return crossed;
}

/* The vertices within reach (in units of L) of (ux, uz) (in units of L):
 * pentagon centres into pent, the others into gap; returns their counts
 * through np and ng. */
static void p1_vertices(double ux, double uz, double reach, struct p1_vertex *pent, int *np,
			struct p1_vertex *gap, int *ng)
{
	static const int classes[4] = {0, 1, 2, 4};
	*np = *ng = 0;
	for (int ci = 0; ci < 4; ci++) {
		int c = classes[ci];
		double h = 0.4 * (reach + (c < 2 ? P1_PHI : 1.0));
		int lo[5], hi[5];
		for (int j = 0; j < 5; j++) {
			double m = 0.4 * (ux * pen_e[j][0] + uz * pen_e[j][1]) + c / 5.0;
			/* Past an int's range (or at an infinite point) the lattice
			 * indices do not fit: no vertex there (the tiling is 0). */
			if (!(fabs(m) < 1e9)) {
				*np = *ng = 0;
				return;
			}
			lo[j] = (int)ceil(m - h);
			hi[j] = (int)floor(m + h);
		}
		for (int k0 = lo[0]; k0 <= hi[0]; k0++)
			for (int k1 = lo[1]; k1 <= hi[1]; k1++)
				for (int k2 = lo[2]; k2 <= hi[2]; k2++)
					for (int k3 = lo[3]; k3 <= hi[3]; k3++) {
						int k4 = c - k0 - k1 - k2 - k3;
						if (k4 < lo[4] || k4 > hi[4])
							continue;
						int k[5] = {k0, k1, k2, k3, k4};
						double x = 0, z = 0, qx = 0, qz = 0;
						for (int j = 0; j < 5; j++) {
							x += k[j] * pen_e[j][0];
							z += k[j] * pen_e[j][1];
							qx += k[j] * pen_f[j][0];
							qz += k[j] * pen_f[j][1];
						}
						if ((x - ux) * (x - ux) + (z - uz) * (z - uz) > reach * reach)
							continue;
						int region = p1_region(c, qx, qz);
						if (region < 0)
							continue;
						struct p1_vertex v = {x * P1_SCALE, z * P1_SCALE, c == 1 || c == 4, region};
						if (c < 2 && *np < P1_MAXV)
							pent[(*np)++] = v;
						else if (c >= 2 && *ng < P1_MAXV)
							gap[(*ng)++] = v;
					}
	}
}

/* The corners of the pentagon centred at v. */
static void p1_corners(const struct p1_vertex *v, struct pt2 out[5])
{
	for (int k = 0; k < 5; k++)
		out[k] = (struct pt2){v->x + P1_CIRCUM * p1_dir[v->orient][k][0],
				      v->z + P1_CIRCUM * p1_dir[v->orient][k][1]};
}

/* How deep (x, z) lies in the pentagon centred at v: its least distance
 * from the edges' lines, negative outside. */
static double p1_depth(const struct p1_vertex *v, double x, double z)
{
	double worst = -INFINITY;
	for (int k = 0; k < 5; k++) {
		double s = -(x - v->x) * p1_dir[v->orient][k][0] - (z - v->z) * p1_dir[v->orient][k][1];
		if (s > worst)
			worst = s;
	}
	return P1_APOTHEM - worst;
}

/* Whether the segment a-b passes through the pentagon centred at v. */
static bool p1_segment_meets(const struct p1_vertex *v, struct pt2 a, struct pt2 b)
{
	double t0 = 0, t1 = 1;
	for (int k = 0; k < 5; k++) {
		const double *u = p1_dir[v->orient][k];
		double fa = -(a.x - v->x) * u[0] - (a.z - v->z) * u[1] - P1_APOTHEM;
		double fb = -(b.x - v->x) * u[0] - (b.z - v->z) * u[1] - P1_APOTHEM;
		if (fa > 0 && fb > 0)
			return false;
		if (fa > 0)
			t0 = fmax(t0, fa / (fa - fb));
		else if (fb > 0)
			t1 = fmin(t1, fa / (fa - fb));
	}
	return t0 < t1;
}

static double segment_dist(struct pt2 p, struct pt2 a, struct pt2 b)
{
	double dx = b.x - a.x, dz = b.z - a.z;
	double t = ((p.x - a.x) * dx + (p.z - a.z) * dz) / (dx * dx + dz * dz);
	t = fmax(0, fmin(1, t));
	return hypot(p.x - a.x - t * dx, p.z - a.z - t * dz);
}

static double penrose_pentagons(double x, double z)
{
	struct p1_vertex pent[P1_MAXV], gap[P1_MAXV];
	int np, ng;
	p1_vertices(x / P1_SCALE, z / P1_SCALE, 1.05, pent, &np, gap, &ng);
	static const int pent_type[3] = {0, 2, 1};
	for (int i = 0; i < np; i++) {
		double d = p1_depth(&pent[i], x, z);
		if (d >= 0)
			return penrose_value(pent_type[pent[i].region], 6, d / PENROSE_BEVEL);
	}
	/* In a gap: its vertex is one that the point sees past no pentagon.
	 * The gap's own pentagons are the neighbours of that vertex, all
	 * within one L of it. */
	struct pt2 p = {x, z};
	const struct p1_vertex *own = NULL;
	double best = INFINITY;
	for (int i = 0; i < ng; i++) {
		double dd = (gap[i].x - x) * (gap[i].x - x) + (gap[i].z - z) * (gap[i].z - z);
		if (dd >= best)
			continue;
		struct pt2 g = {gap[i].x, gap[i].z};
		bool hidden = false;
		for (int k = 0; k < np && !hidden; k++)
			hidden = p1_segment_meets(&pent[k], g, p);
		if (!hidden) {
			best = dd;
			own = &gap[i];
		}
	}
	if (!own)
		return 0;   /* not reached: every gap holds a vertex */
	struct p1_vertex near[P1_MAXV], unused[P1_MAXV];
	int nn, nu;
	p1_vertices(own->x / P1_SCALE, own->z / P1_SCALE, 1.05, near, &nn, unused, &nu);
	double d = INFINITY, ray = INFINITY, ray_t = INFINITY;
	double rx = x - own->x, rz = z - own->z;
	for (int i = 0; i < nn; i++) {
		struct pt2 c[5];
		p1_corners(&near[i], c);
		for (int k = 0; k < 5; k++) {
			struct pt2 a = c[k], b = c[(k + 1) % 5];
			d = fmin(d, segment_dist(p, a, b));
			/* where the ray own + t (p - own) meets a-b */
			double ex = b.x - a.x, ez = b.z - a.z;
			double den = rz * ex - rx * ez;
			if (fabs(den) < 1e-12)
				continue;
			double ax = a.x - own->x, az = a.z - own->z;
			double t = (az * ex - ax * ez) / den, s = (rx * az - rz * ax) / den;
			if (t > 0 && s >= -1e-9 && s <= 1 + 1e-9 && t < ray_t) {
				ray_t = t;
				ray = fabs((x - a.x) * ez - (z - a.z) * ex) / hypot(ex, ez);
			}
		}
	}
	if (own->region < 2)
		d = fmin(d, ray);
	return penrose_value(3 + own->region, 6, d / PENROSE_BEVEL);
}

PATTERN_FN(tiling)
{
	(void)ctx;
	int n = pt->n[0];
	/* measured: POV-Ray's Penrose tilings give 1 within 1e-10 of the origin */
	if (n >= 25 && n <= 27 && hypot(q.x, q.z) <= 1e-10)
		return 1;
	if (n == 27)
		return penrose_rhombi(q.x, q.z);
	if (n == 26)
		return penrose_kites(q.x, q.z);
	if (n == 25)
		return penrose_pentagons(q.x, q.z);
	if (n < 1 || n > TILING_COUNT || tiling_defs[n - 1].ntypes == 0)
		return 0;
	return tiling_at(&tiling_defs[n - 1], q.x, q.z);
}

/* pavement.c: the pavement pattern (see kinds.h), as POV-Ray 3.7 computes it.
 *
 * The x-z plane (y is ignored) is cut into cells, unit squares, unit
 * triangles or hexagons of side 1, grouped into tiles by a measured
 * periodic layout (pavement_table.h). The value at a point depends on its
 * distance d from the border of its tile, measured around the corners of
 * its own cell: 1 - min(d, w)/w, w the bevel width (1/2 for squares, the
 * unit triangle's inradius 1/(2 sqrt 3) for triangles and hexagons): 1 on
 * the borders, 0 in the middle of the tiles.
 *
 * The corners are where `exterior`, `interior` and `form` act:
 * - exterior: the corners where the tile is one cell wide (a square's 90,
 *   a triangle's 60 degrees);
 * - form: the 120 degree corners of triangles and hexagons, and the cells of
 *   squares where a one-cell-wide tile turns (the elbows);
 * - interior: the corners where a cell's two edges at a vertex are inside
 *   the tile but the tile does not surround the vertex (concave corners).
 * Each is 0 pointy (the distance to the nearest edge line), 1 cut by a
 * chamfer, 2 rounded. Every formula below was fitted to POV-Ray's values
 * at 6400 points of each of the 112 layouts, for every setting, and
 * matches them to 3e-8 (tests/unit/test_pavement.c holds samples). */
#include "pattern/kinds.h"
#include "pattern/pavement_table.h"

#include <math.h>
#include <stddef.h>

#define SQRT3 1.7320508075688772
#define H (SQRT3 / 2)             /* the unit triangle's height */
#define W3 (1 / (2 * SQRT3))      /* the bevel width of triangles and hexagons */

static const unsigned char tile_counts[3][6] = {{1, 1, 1, 3, 4, 12}, {1, 1, 2, 5, 12, 35}, {1, 1, 3, 7, 22, 0}};

int pavement_pattern_count(int sides, int tiles)
{
	int s = sides == 3 ? 0 : sides == 4 ? 1 : sides == 6 ? 2 : -1;
	if (s < 0 || tiles < 1 || tiles > 6)
		return 0;
	return tile_counts[s][tiles - 1];
}

/* The layout of pavement (sides, tiles, pattern), or NULL. */
static const struct pavement_layout *find_layout(int sides, int tiles, int pattern)
{
	int s = sides == 3 ? 0 : sides == 4 ? 1 : sides == 6 ? 2 : -1;
	if (s < 0 || tiles < 1 || tiles > 6 || pattern < 1 || pattern > tile_counts[s][tiles - 1])
		return NULL;
	int k = 0;
	for (int i = 0; i < s; i++)
		for (int t = 0; t < 6; t++)
			k += tile_counts[i][t];
	for (int t = 0; t < tiles - 1; t++)
		k += tile_counts[s][t];
	return &pavement_layouts[k + pattern - 1];
}

/* The mask of the cell at lattice point (i, j) (sub-cell d for triangles). */
static unsigned cell_mask(const struct pavement_layout *l, double i, double j, int d)
{
	double k = floor(j / l->r);
	double fj = j - k * l->r, x = i - k * l->q;
	double fi = x - floor(x / l->p) * l->p;
	int jj = fj >= 0 && fj < l->r ? (int)fj : -1;
	int ii = fi >= 0 && fi < l->p ? (int)fi : -1;
	if (jj < 0 || jj >= l->r || ii < 0 || ii >= l->p)
		jj = ii = 0; /* beyond double precision's reach (|x| > 2^52) */
	int idx = jj * l->p + ii;
	return l->mask[l->sides == 3 ? 2 * idx + d : idx];
}

static double clamp01w(double d, double w)
{
	if (d < 0)
		d = 0;
	if (d > w)
		d = w;
	return 1 - d / w;
}

/* A convex corner of angle theta (60 or 120 degrees) between two edge lines
 * at distances a and b from the point, rounded by the arc of radius r
 * tangent to both: the distance from the rounded border. */
static double rounded(double a, double b, double theta, double r)
{
	double s = sin(theta), c = cos(theta);
	double y = a, x = (b + a * c) / s;      /* line a is the x axis, the corner at 0 */
	double t = r * (1 + c) / s;              /* the tangent points' distance from the corner */
	if (x < t && x * c + y * s < t)
		return r - hypot(x - t, y - r);
	return fmin(a, b);
}

/* ---- squares ---- */

/* Whether the neighbour (dx, dz) of a square cell is in its tile. */
static bool sq_in(unsigned m, int dx, int dz)
{
	static const signed char bit[3][3] = {{5, 4, 3}, {6, -1, 2}, {7, 0, 1}};  /* [dx+1][dz+1] */
	return m >> bit[dx + 1][dz + 1] & 1;
}

static double square_value(unsigned m, double u, double w, int form, int ext, int inn)
{
	const double rho = 0.5;
	/* An elbow: exactly two sides in the tile, at right angles, and the
	 * cell between them not. */
	int ex = 0, ez = 0, nside = 0;
	if (sq_in(m, 1, 0)) { ex += 1; nside++; }
	if (sq_in(m, -1, 0)) { ex -= 1; nside++; }
	if (sq_in(m, 0, 1)) { ez += 1; nside++; }
	if (sq_in(m, 0, -1)) { ez -= 1; nside++; }
	if (nside == 2 && ex && ez && !sq_in(m, ex, ez) && (form == 1 || form == 2)) {
		/* the tile turns across the cell around the inner corner */
		double U = ex > 0 ? u : 1 - u, V = ez > 0 ? w : 1 - w;  /* from the outer corner */
		double d;
		if (form == 1) {
			d = fmin(U + V - 1, 2 - U - V);
		} else {
			double r = hypot(1 - U, 1 - V);
			d = fmin(r, 1 - r);
		}
		return clamp01w(d, rho);
	}
	/* otherwise the quadrant's corner decides */
	int sx = u >= 0.5 ? 1 : -1, sz = w >= 0.5 ? 1 : -1;
	double du = sx > 0 ? 1 - u : u, dv = sz > 0 ? 1 - w : w;
	bool a = sq_in(m, sx, 0), b = sq_in(m, 0, sz), diag = sq_in(m, sx, sz);
	bool elbow_far = sq_in(m, -sx, 0) && sq_in(m, 0, -sz);  /* the quadrant faces away from an elbow's turn */
	double d;
	if (!a && !b) {
		if (elbow_far && !sq_in(m, -sx, -sz))
			d = fmin(du, dv);  /* an elbow's outer corner: its form */
		else if (ext == 1)
			d = du + dv - rho;
		else if (ext == 2)
			d = rho - hypot(rho - du, rho - dv);
		else
			d = fmin(du, dv);
	} else if (a && !b) {
		d = dv;
	} else if (b && !a) {
		d = du;
	} else if (!diag) {
		if (form != 3 && !sq_in(m, -sx, 0) && !sq_in(m, 0, -sz))
			d = fmax(du, dv);  /* an elbow's inner corner */
		else if (inn == 1)
			d = du + dv;
		else if (inn == 2)
			d = hypot(du, dv);
		else
			d = fmax(du, dv);
	} else {
		d = rho;
	}
	return clamp01w(d, rho);
}

/* ---- triangles and hexagons ---- */

/* The distance at a 120 degree corner between edge lines at a and b. */
static double corner120(double a, double b, int form)
{
	if (form == 1)
		return fmin(fmin(a, b), 2 * (a + b) / 3 - W3);
	if (form == 2)
		return rounded(a, b, 2 * M_PI / 3, H);
	return fmin(a, b);
}

/* The distance at a 60 degree wedge of a cell whose two edges at the vertex
 * (at a and b) are inside the tile: a concave corner. */
static double concave60(double a, double b, int inn)
{
	if (inn == 1)
		return fmax(a, b) + 0.5 * fmin(a, b);
	if (inn == 2)
		return sqrt(a * a + b * b + a * b);
	return a + b;
}

/* The signed distance of (px, pz) from the line through the origin at
 * angle k * 60 degrees, positive on its counter-clockwise side. */
static double side60(double px, double pz, int k)
{
	static const double c[6] = {1, 0.5, -0.5, -1, -0.5, 0.5};
	static const double s[6] = {0, H, H, 0, -H, -H};
	k = ((k % 6) + 6) % 6;
	return pz * c[k] - px * s[k];
}

static double triangle_value(const struct pavement_layout *l, double x, double z, int form, int ext, int inn)
{
	double t = z / H, s = x - 0.5 * t;
	double i = floor(s), j = floor(t);
	int dn = (s - i) + (t - j) >= 1;
	unsigned m = cell_mask(l, i, j, dn);
	/* the vertices (lattice offsets) and the direction of the cell around each */
	static const int vx[2][3] = {{0, 1, 0}, {1, 1, 0}}, vz[2][3] = {{0, 0, 1}, {0, 1, 1}};
	static const int k0s[2][3] = {{0, 2, 4}, {1, 3, 5}};
	double best = W3;
	for (int v = 0; v < 3; v++) {
		unsigned sec = m >> (5 * v) & 31;   /* bit n-1: the n-th triangle counter-clockwise */
		if (sec == 31)
			continue;
		double vi = i + vx[dn][v], vj = j + vz[dn][v];
		double px = x - (vi + 0.5 * vj), pz = z - vj * H;
		int k0 = k0s[dn][v];
		double e1 = side60(px, pz, k0), e2 = -side60(px, pz, k0 + 1);
		bool next = sec & 1, prev = sec >> 4 & 1;
		double d;
		if (!next && !prev) {
			if (ext == 1)
				d = fmin(fmin(e1, e2), e1 + e2 - W3);
			else if (ext == 2)
				d = rounded(e1, e2, M_PI / 3, W3);
			else
				d = fmin(e1, e2);
		} else if (next && prev) {
			d = concave60(e1, e2, inn);
		} else if (next) {
			d = sec & 2 ? e1 : corner120(e1, -side60(px, pz, k0 + 2), form);
		} else {
			d = sec & 8 ? e2 : corner120(e2, side60(px, pz, k0 - 1), form);
		}
		if (d < best)
			best = d;
	}
	return clamp01w(best, W3);
}

static double hexagon_value(const struct pavement_layout *l, double x, double z, int form, int inn)
{
	/* the nearest centre (1 + 1.5 m, (m + 2 n) H) */
	double mf = floor((x - 1) / 1.5);
	double bm = 0, bn = 0, best2 = INFINITY;
	/* whole offsets: past 2^53 mf + 1 is mf (a loop on m never ended) */
	for (int a = 0; a <= 1; a++) {
		double m = mf + a;
		double nf = floor((z - H * m) / (2 * H));
		for (int b = 0; b <= 1; b++) {
			double n = nf + b;
			double dx = x - (1 + 1.5 * m), dz = z - (m + 2 * n) * H;
			double d2 = dx * dx + dz * dz;
			if (d2 < best2) {
				best2 = d2;
				bm = m;
				bn = n;
			}
		}
	}
	unsigned msk = cell_mask(l, bm, bn, 0);
	double px = x - (1 + 1.5 * bm), pz = z - (bm + 2 * bn) * H;
	/* the distances from the six edges, edge e's outward normal at 30 + 60 e degrees */
	static const double nx[6] = {H, 0, -H, -H, 0, H}, nz[6] = {0.5, 1, 0.5, -0.5, -1, -0.5};
	double e[6];
	for (int k = 0; k < 6; k++)
		e[k] = H - (px * nx[k] + pz * nz[k]);
	double best = W3;
	for (int k = 0; k < 6; k++) {
		/* the corner at 60 k degrees between edges k-1 and k */
		int a = (k + 5) % 6, b = k;
		bool ina = msk >> a & 1, inb = msk >> b & 1;
		double d;
		if (ina && inb)
			continue;
		if (!ina && !inb) {
			d = corner120(e[a], e[b], form);
		} else {
			double bord = ina ? e[b] : e[a], own = ina ? e[a] : e[b];
			d = own < bord ? concave60(own, bord - own, inn) : bord;
		}
		if (d < best)
			best = d;
	}
	return clamp01w(best, W3);
}

PATTERN_FN(pavement)
{
	(void)ctx;
	const struct pavement_layout *l = find_layout(pt->n[0], pt->n[1], pt->n[2]);
	if (!l)
		return 0;
	int ext = pt->n[3], inn = pt->n[4], form = pt->n[5];
	if (l->sides == 4) {
		double i = floor(q.x), j = floor(q.z);
		return square_value(cell_mask(l, i, j, 0), q.x - i, q.z - j, form, ext, inn);
	}
	if (l->sides == 3)
		return triangle_value(l, q.x, q.z, form, ext, inn);
	return hexagon_value(l, q.x, q.z, form, inn);
}

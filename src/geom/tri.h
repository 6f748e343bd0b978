/* tri.h: the watertight ray/triangle test shared by triangle.c and mesh.c
 * (Woop, Benthin & Wald 2013). A ray is prepared once (tri_ray_init); each
 * triangle is then tested against it by shearing its vertices into a frame
 * where the ray runs along the dominant axis and testing the origin against
 * the three 2D edge functions.
 *
 * Watertightness: the edge functions are computed with an exact sign (a
 * zero double result is re-evaluated from the products' rounding errors,
 * which are exact), and an edge function that is exactly zero is decided
 * by a symbolic perturbation of the ray, the same for every triangle of the
 * ray. So a ray through a shared edge or vertex of a closed mesh crosses
 * exactly one triangle on each side it enters or leaves: never none, never
 * two, and crossing counts along a line are always even. (This needs the
 * products in the edge functions rounded separately: tri.c switches
 * floating-point contraction off for itself.) */
#ifndef LUCENT_TRI_H
#define LUCENT_TRI_H

#include "math/vec.h"

#include <stdbool.h>

/* A ray prepared for triangle tests. */
struct tri_ray {
	vec3 org;
	int kx, ky, kz;   /* axis permutation: kz is the dominant direction axis */
	double sx, sy, sz; /* shear: dir[kx]/dir[kz], dir[ky]/dir[kz], 1/dir[kz] */
};

/* A triangle hit: t and the barycentric weights of b (u) and c (v); the
 * weight of a is 1 - u - v. */
struct tri_hit {
	double t, u, v;
};

/* Prepare r; false (and nothing can be hit) when its direction is zero or
 * not finite. */
bool tri_ray_init(struct tri_ray *tr, const struct ray *r);

/* Does the prepared ray cross triangle abc at tmin < t < tmax? Fills *out
 * on a hit. Both faces count. A triangle whose projection along the ray is
 * degenerate is never hit; t is always finite. */
bool tri_intersect(const struct tri_ray *tr, vec3 a, vec3 b, vec3 c, double tmin, double tmax, struct tri_hit *out);

/* Is abc degenerate (zero area, or a non-finite corner)? POV-Ray drops
 * such triangles. */
bool tri_degenerate(vec3 a, vec3 b, vec3 c);

/* Is the stand-alone smooth_triangle { a, na, b, nb, c, nc } degenerate?
 * POV-Ray drops it (with a warning) when abc is degenerate or the vertex
 * normals do not all point strictly to the same side of its plane; inside
 * a mesh the normals are not checked. */
bool tri_smooth_degenerate(vec3 a, vec3 na, vec3 b, vec3 nb, vec3 c, vec3 nc);

/* Barycentric weights (of b and c) of the point of abc's plane nearest to
 * p; (0,0) for a degenerate triangle. For callers without a hit record. */
void tri_barycentric(vec3 a, vec3 b, vec3 c, vec3 p, double *u, double *v);

#endif

/* sweep.h: the builder API of sphere_sweep { ... } (src/geom/sweep.c):
 * the solid a sphere sweeps out as its centre and radius follow a spline
 * through the given spheres. linear_spline joins consecutive spheres
 * (n - 1 pieces, each the convex hull of its two spheres); b_spline is the
 * uniform cubic B-spline of the centres and radii (n - 3 pieces, not
 * passing through the spheres); cubic_spline is the Catmull-Rom spline
 * (n - 3 pieces, through the second to the last but one sphere).
 * doc/objects.md describes the object and how closely it follows POV-Ray. */
#ifndef LUCENT_SWEEP_H
#define LUCENT_SWEEP_H

#include "scene/object.h"

enum sweep_spline { SWEEP_LINEAR, SWEEP_B_SPLINE, SWEEP_CUBIC };

/* The fewest spheres the spline takes (2 for linear, 4 for the others). */
int sweep_min_spheres(enum sweep_spline kind);

/* A new sphere_sweep through the n spheres centre[i], radius[i] (n at
 * least sweep_min_spheres(kind); the caller checks it). The arrays are
 * copied. Depth tolerance 1e-6. Caller owns the result; free with
 * object_free. */
struct object *sweep_new(enum sweep_spline kind, const vec3 *center, const double *radius, int n,
                         struct srcpos pos);
/* tolerance F: crossings closer than this to the ray's origin (in object
 * space, along the unit direction) are not reported. */
void sweep_set_tolerance(struct object *o, double tol);

#endif

/* shapes2.h: constructors for the primitives of the second round (polygon,
 * lathe, sor, isosurface), the part of the builder API that makes them.
 * Each returns a new object (caller owns it; free with object_free) with no
 * texture and the identity transform. doc/objects.md describes each shape
 * and how closely it follows POV-Ray. */
#ifndef LUCENT_SHAPES2_H
#define LUCENT_SHAPES2_H

#include "scene/object.h"

struct fn;

/* polygon { n, points }: the n points (3-D; a 2-D one has z = 0), cut into
 * sub-polygons as POV-Ray does (a sub-polygon ends at the point equal to
 * its first; the last one is closed if it is not: *closed_last, may be
 * NULL, is set then). The plane is that of the first three points that
 * are not on one line. When every point is on one line, or some point is
 * off that plane (*nonplanar is set then; may be NULL), the polygon is
 * never hit, as in POV-Ray. */
struct object *polygon_new(const vec3 *pts, int n, struct srcpos pos, bool *closed_last, bool *nonplanar);

/* lathe { spline n, points }: the 2-D curve through points (r, y) turned
 * about the y axis. The pieces follow the same rules as POV-Ray's:
 * linear n - 1 pieces, quadratic n - 2 (the first point is a control
 * point), cubic n - 3 (the first and last are), bezier n / 4. The caller
 * checks the counts (at least 2, 3, 4 points; bezier a multiple of 4). */
enum lathe_spline { LATHE_LINEAR_SPLINE, LATHE_QUADRATIC_SPLINE, LATHE_CUBIC_SPLINE, LATHE_BEZIER_SPLINE };
struct object *lathe_new(enum lathe_spline spline, const double (*pts)[2], int n, struct srcpos pos);
void lathe_set_sturm(struct object *o, bool sturm);

/* sor { n, points }: r^2 a cubic in y on each of the n - 3 pieces between
 * points 1 and n - 2, with the slopes the manual's formula gives, and caps
 * (unless open) at both ends. The caller checks n >= 4 and that the
 * heights increase (sor_check). */
struct object *sor_new(const double (*pts)[2], int n, struct srcpos pos);
/* The first index i (1..n-1) whose height does not exceed the one before
 * among the points the pieces pass through (POV-Ray's rule, see sor.c),
 * or -1 when they are fine. */
int sor_check(const double (*pts)[2], int n);
void sor_set_open(struct object *o, bool open);
void sor_set_sturm(struct object *o, bool sturm);

/* isosurface { function { f } ... }: the surface f(x, y, z) = threshold
 * inside a container (a box or a sphere). f is referenced (the object
 * holds one reference). The settings start at POV-Ray's defaults
 * (threshold 0, accuracy 0.001, max_gradient 1.1, the box <-1,-1,-1>,
 * <1,1,1>, max_trace 1) and are changed with the setters below. */
struct object *isosurface_new(struct fn *f, struct srcpos pos);
void isosurface_set_box(struct object *o, vec3 c1, vec3 c2);
void isosurface_set_sphere(struct object *o, vec3 center, double radius);
void isosurface_set_threshold(struct object *o, double threshold);
void isosurface_set_accuracy(struct object *o, double accuracy);
void isosurface_set_max_gradient(struct object *o, double max_gradient);
void isosurface_set_evaluate(struct object *o, double p0, double p1, double p2);
void isosurface_set_open(struct object *o, bool open);
/* max_trace n (n >= 1), or all_intersections (n = 0). */
void isosurface_set_max_trace(struct object *o, int n);
/* The greatest gradient the surface searches met so far (for POV-Ray's
 * warning after the render), and the max_gradient it was given; false if
 * the object is not an isosurface. */
bool isosurface_gradient_report(const struct object *o, double *found, double *given);

#endif

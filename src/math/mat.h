/* mat.h: 4x4 affine transforms. Matrices are named destination-from-source
 * (world_from_object), so a chain of products reads right to left:
 * world_from_object = world_from_parent * parent_from_object.
 * POV-Ray's conventions hold: a left-handed frame, and rotate <a,b,c>
 * turns about x by a, then y by b, then z by c (degrees). */
#ifndef LUCENT_MAT_H
#define LUCENT_MAT_H

#include "math/vec.h"
#include <stdbool.h>

typedef struct mat4 {
	double m[4][4]; /* row-major; points are columns: p' = M p */
} mat4;

/* A transform with its inverse, kept together so neither is recomputed. */
struct xform {
	mat4 fwd; /* destination_from_source */
	mat4 inv; /* source_from_destination */
	bool simple; /* one translate, rotate or scale by equal factors, as written: POV-Ray
	              * keeps a sphere's box exact under these (see sphere.c); matrix,
	              * compose and invert (so every transform block) give false */
};

mat4 mat_identity(void);
mat4 mat_mul(const mat4 *a, const mat4 *b); /* a * b: apply b first */
mat4 mat_transpose(const mat4 *a);
/* Inverse of an affine matrix; returns false (and identity) if singular. */
bool mat_inverse(const mat4 *a, mat4 *out);
bool mat_is_identity(const mat4 *a);

vec3 mat_point(const mat4 *m, vec3 p);   /* M p, w = 1 */
vec3 mat_dir(const mat4 *m, vec3 d);     /* M d, w = 0 */
/* Transform a normal by the transpose of inv (inv = the inverse of the
 * matrix that moved the surface), i.e. the inverse transpose. */
vec3 mat_normal(const mat4 *inv, vec3 n);

struct xform xform_identity(void);
struct xform xform_translate(vec3 t);
/* Scale; a zero component is replaced by 1 by the caller's policy, not here:
 * a singular scale gives a non-invertible transform (inv = identity). */
struct xform xform_scale(vec3 s);
struct xform xform_rotate(vec3 degrees);
/* The same rotation with sines and cosines as computed, not snapped at
 * multiples of 90 degrees: the last bits POV-Ray's vrotate() prints. */
struct xform xform_rotate_plain(vec3 degrees);
/* Rotation by DEGREES about the unit vector AXIS (right-handed about AXIS
 * in lucent's column convention, as vaxis_rotate() turns), its elements
 * rounded as POV-Ray's axis rotation matrix. */
mat4 mat_axis_rotation(vec3 axis, double degrees);
/* A 4x3 matrix as POV-Ray's `matrix <a..l>`: rows are x, y, z images and
 * the translation. */
struct xform xform_matrix(const double v[12]);
/* outer then inner: apply `inner` first, then `outer`. */
struct xform xform_compose(const struct xform *outer, const struct xform *inner);
struct xform xform_invert(const struct xform *a);

/* The world-space box enclosing a transformed object-space box. */
struct aabb mat_bounds(const mat4 *m, struct aabb b);

#endif

/* shapes.h: constructors for the primitives in src/geom/, the part of the
 * builder API that makes objects. Each returns a new object (caller owns it;
 * free with object_free) with no texture and the identity transform. */
#ifndef LUCENT_SHAPES_H
#define LUCENT_SHAPES_H

#include "scene/object.h"

struct object *sphere_new(vec3 center, double radius, struct srcpos pos);
/* plane { normal, distance }: the points p with dot(p, n̂) = distance*|n|/|n|
 * as POV-Ray defines it; the inside is the side the normal points away from. */
struct object *plane_new(vec3 normal, double distance, struct srcpos pos);
/* box { corner1, corner2 } in any order. */
struct object *box_new(vec3 c1, vec3 c2, struct srcpos pos);

#endif

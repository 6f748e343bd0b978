/* csg.h: constructive solid geometry: union, merge, intersection and
 * difference of any objects, with the children in their own BVH. */
#ifndef LUCENT_CSG_H
#define LUCENT_CSG_H

#include "scene/object.h"

enum csg_kind { CSG_UNION, CSG_MERGE, CSG_INTERSECTION, CSG_DIFFERENCE };

/* A new, empty CSG object (caller owns it; free with object_free). */
struct object *csg_new(enum csg_kind kind, struct srcpos pos);
/* Append a child; the CSG takes ownership. For a difference the first
 * child is the one the others are cut from. */
void csg_add(struct object *csg, struct object *child);
/* Is o a CSG object? If so and kind is not NULL, which kind. */
bool csg_kind_of(const struct object *o, enum csg_kind *kind);
/* Call once o is complete, and again after its own `inverse` changes:
 * every union under an inversion in o (o's own, a subtracted child's place
 * in a difference, an inverse child) then shows only its outer surface, as
 * POV-Ray's inverted union (an intersection of inverted children) does.
 * Children settled before keep what they learned; nothing else changes. */
void csg_settle(struct object *o);
/* split_union on/off (union only; on by default). */
void csg_set_split(struct object *csg, bool split);
/* May prepare put o's children straight into the scene's hierarchy? True
 * for a union with split_union on, no clip, no bound and no inversion. */
bool csg_splittable(const struct object *o);

#endif

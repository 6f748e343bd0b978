/* bvh.h: a bounding volume hierarchy over objects, built with the surface
 * area heuristic over binned centroids. Objects with infinite bounds are
 * not put in it: the caller keeps them aside. */
#ifndef LUCENT_BVH_H
#define LUCENT_BVH_H

#include "scene/object.h"

#include <stddef.h>

struct bvh;

/* Build over objs[0..n) (world bounds in o->bounds, all finite). The BVH
 * keeps its own array of pointers; the objects stay the caller's. */
struct bvh *bvh_build(struct object *const *objs, size_t n);
void bvh_free(struct bvh *b);
size_t bvh_node_count(const struct bvh *b);

/* Closest hit with tmin < t < tmax; on a hit fills h (h->obj is the
 * primitive hit) and, if top is not NULL, *top with the object of the
 * hierarchy that contains it. `skip` is a mask of object flags whose
 * objects are ignored. */
bool bvh_intersect(const struct bvh *b, const struct ray *r, double tmin, double tmax, unsigned skip, struct hit *h,
                   const struct object **top);
/* Is p inside some object of the hierarchy other than `exclude`? */
bool bvh_inside_any(const struct bvh *b, vec3 p, const struct object *exclude);
/* Any hit with tmin < t < tmax among objects without a `skip` flag; the
 * object found is stored in *blocker. */
bool bvh_occluded(const struct bvh *b, const struct ray *r, double tmin, double tmax, unsigned skip, const struct object **blocker);

#endif

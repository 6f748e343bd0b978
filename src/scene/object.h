/* object.h: the common header every shape starts with, and the table of
 * operations each primitive provides. A primitive's own struct embeds
 * `struct object` as its first member and is private to its file in
 * src/geom/. Transforms are world_from_object; the operations work in
 * object space on rays whose direction is not renormalised, so the
 * parameter t of a hit is the same in both spaces. */
#ifndef LUCENT_OBJECT_H
#define LUCENT_OBJECT_H

#include "lang/source.h"
#include "math/mat.h"
#include "scene/texture.h"

#include <stdbool.h>

struct object;

/* One intersection. `part` tells the primitive which face or piece was hit
 * so that the normal need not be searched for again. */
struct hit {
	double t;
	const struct object *obj;
	int part;
};

enum object_flag {
	OBJ_NO_SHADOW = 1 << 0,
	OBJ_NO_IMAGE = 1 << 1,
	OBJ_NO_REFLECTION = 1 << 2,
	OBJ_INVERSE = 1 << 3,
	OBJ_HOLLOW = 1 << 4,
	OBJ_DOUBLE_ILLUMINATE = 1 << 5,
};

struct object_ops {
	const char *name;
	/* Closest hit with tmin < t < tmax along the object-space ray r; fills
	 * h->t and h->part. */
	bool (*intersect)(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h);
	/* Every surface crossing with tmin < t < tmax, in increasing t, up to
	 * max; returns how many (for CSG). */
	int (*all_hits)(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out, int max);
	/* Is the object-space point inside the solid? */
	bool (*inside)(const struct object *o, vec3 p);
	/* The outward object-space normal (not necessarily unit) at p. */
	vec3 (*normal)(const struct object *o, vec3 p, const struct hit *h);
	/* Object-space bounds; infinite components for unbounded shapes. */
	struct aabb (*bounds)(const struct object *o);
	/* A deep copy of the primitive (shared buffers referenced). */
	struct object *(*copy)(const struct object *o);
	/* Free what the primitive owns beyond the header (may be NULL). */
	void (*destroy)(struct object *o);
};

struct object {
	const struct object_ops *ops;
	struct xform xf;          /* world_from_object (fwd) and its inverse */
	bool has_xf;              /* false: xf is the identity, skip it */
	struct texture *tex;      /* one reference; NULL until the parser sets it */
	unsigned flags;           /* enum object_flag */
	struct aabb bounds;       /* world-space bounds, set by prepare */
	struct srcpos pos;        /* where the statement began */
	unsigned id;              /* creation order, for stable output */
};

/* Initialise the header of a freshly allocated primitive. */
void object_init(struct object *o, const struct object_ops *ops, struct srcpos pos);
/* Apply a transform after the object's current one. */
void object_transform(struct object *o, const struct xform *t);
/* Deep copy: the primitive, its transform and a new reference to its texture. */
struct object *object_copy(const struct object *o);
void object_free(struct object *o);

/* World-space closest hit: carries r into object space when needed. */
bool object_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h);
/* World-space unit normal at world point p for hit h. */
vec3 object_normal(const struct object *o, vec3 p, const struct hit *h);
/* World-space inside test (honours OBJ_INVERSE). */
bool object_inside(const struct object *o, vec3 p);
/* World-space bounds from the object-space ones and the transform. */
struct aabb object_world_bounds(const struct object *o);

#endif

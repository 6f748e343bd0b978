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
	double u, v; /* primitive-specific (a triangle's barycentrics) */
	bool inverted; /* object_intersect: an odd number of inverse objects lie between
	                * the object asked and the leaf (POV-Ray's trace() normal flips) */
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
	/* Object-space bounds; infinite components for unbounded shapes (a
	 * plane's half-space may be infinite on one side only). */
	struct aabb (*bounds)(const struct object *o);
	/* Object-space bounds of the inverse solid (a plane: the other
	 * half-space); NULL: an inverse object is unbounded. */
	struct aabb (*inverse_bounds)(const struct object *o);
	/* POV-Ray's uv coordinates of the object-space point p for hit h;
	 * NULL for primitives that have none. */
	bool (*uv)(const struct object *o, vec3 p, const struct hit *h, double uv[2]);
	/* The texture at hit h when the primitive has several (mesh triangles);
	 * NULL: the object's own. Returns NULL to mean the object's own. */
	struct texture *(*texture_at)(const struct object *o, const struct hit *h);
	/* Several textures blended at the object-space point p (a blob's
	 * component textures, weighted by their fields): up to max textures
	 * (NULL: the object's own) and weights summing to 1; returns how many,
	 * 0 meaning texture_at or the object's own. May be NULL. */
	int (*texture_blend)(const struct object *o, vec3 p, const struct texture **tex, double *w, int max);
	/* Apply t to the textures the primitive carries besides the object's
	 * own (object_transform_textures calls it); may be NULL. */
	void (*transform_textures)(struct object *o, const struct xform *t);
	/* The textures the primitive carries besides the object's own (a
	 * mesh's triangle textures), for prepare's feature analysis; may be
	 * NULL (none). */
	size_t (*textures)(const struct object *o, struct texture *const **tex);
	/* CSG only (NULL elsewhere): the children, for operations that walk
	 * the tree (transforms, textures, flags, prepare). */
	size_t (*children)(struct object *o, struct object ***kids);
	/* May be NULL: object_transform calls it with t before the object (a
	 * CSG: its children) moves. POV-Ray keeps a CSG's box from before its
	 * first transform and moves that box (a rotated cube of planes stays
	 * bounded); a sphere notes whether t keeps its box exact. */
	void (*transform_bounds)(struct object *o, const struct xform *t);
	/* May be NULL (then: bounds moved by xf): the world-space bounds, for
	 * a primitive whose box POV-Ray keeps better than its object-space
	 * box moved by the transform (a sphere only translated, rotated and
	 * scaled by equal factors). */
	struct aabb (*world_bounds)(const struct object *o);
	/* Build what the object needs before rendering (CSG: its own BVH),
	 * after its children have been prepared; may be NULL. */
	void (*prepare)(struct object *o);
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
	struct interior *interior; /* one reference; NULL: the default (ior 1, no fading) */
	unsigned flags;           /* enum object_flag */
	struct aabb bounds;       /* world-space bounds, set by prepare */
	bool loose;               /* set by prepare: the inside may reach beyond bounds (an
	                           * inverse part; a box from bounded_by), so inside tests
	                           * must not cull by them */
	struct object *clip;      /* clipped_by: hits count only inside it; owned */
	struct object *bound;     /* bounded_by: rays that miss it skip the object; owned */
	struct srcpos pos;        /* where the statement began */
	unsigned id;              /* creation order, for stable output */
	int light_group;          /* the light_group it belongs to (0: none): which lights reach it */
	int carried_lights;       /* CSG: the group (a carrier, see light.h) of the light_sources
	                           * read in its body; 0: none */
};

/* Initialise the header of a freshly allocated primitive. */
void object_init(struct object *o, const struct object_ops *ops, struct srcpos pos);
/* Apply a transform after the object's current one (to a CSG's children,
 * and to clipped_by and bounded_by objects). */
void object_transform(struct object *o, const struct xform *t);
/* Apply t to the textures o and its descendants already have (an
 * object's transformation moves the textures given before it). */
void object_transform_textures(struct object *o, const struct xform *t);
/* Set flags on o and, for CSG, on every descendant. */
void object_set_flags(struct object *o, unsigned flags);
/* Give t (a new reference each) to o, or for CSG to every descendant
 * that has no texture yet. */
void object_fill_texture(struct object *o, struct texture *t);
/* Give in (a new reference each) to the descendants of a CSG that have no
 * interior yet. */
void object_fill_interior(struct object *o, struct interior *in);
/* Prepare o and everything below it: world bounds in o->bounds, CSG
 * hierarchies. Call after the last transform. */
void object_prepare(struct object *o);
/* Deep copy: the primitive, its transform and a new reference to its texture. */
struct object *object_copy(const struct object *o);
void object_free(struct object *o);

/* all_hits from the ascending roots t[0..n) of a primitive already cut to
 * its interval: fills out (at most max), part = the root's index. */
int object_hits_from_roots(const struct object *o, const double *t, int n, struct hit *out, int max);

/* World-space closest hit: carries r into object space when needed,
 * honours clipped_by and bounded_by. h->obj is the primitive hit (a leaf,
 * for CSG). */
bool object_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h);
/* World-space unit normal at world point p for hit h. */
vec3 object_normal(const struct object *o, vec3 p, const struct hit *h);
/* World-space inside test (honours OBJ_INVERSE). */
bool object_inside(const struct object *o, vec3 p);
/* World-space bounds, as POV-Ray's min_extent/max_extent give them: the
 * object-space box transformed, or the box of the clip or the bound when
 * that is smaller by volume; a box unbounded on any axis (or empty)
 * becomes the infinite box. An inverse object keeps the box it had (the
 * other half-space for a plane): its surface lies in it, its inside does
 * not (see `loose`). */
struct aabb object_world_bounds(const struct object *o);
/* Box b as POV-Ray stores a box: its low corner and its size in single
 * precision, the high corner their sum rounded to single precision again
 * (measured: triangle { <0.3,0.1,0.2>, <1,0.5,0.25>, <0.2,0.9,0.3> }
 * reports y from 0.100000001490 to 0.900000035763). Sides are clamped to
 * +-1e10 first, POV-Ray's unbounded box. */
struct aabb object_box_single(struct aabb b);
/* Does the ray meet box b with tmin <= t <= tmax? (A margin of 1e-9 of
 * the box's size keeps hits on its faces.) An infinite box always meets. */
bool object_ray_meets_box(struct aabb b, const struct ray *r, double tmin, double tmax);
/* The same before that last step: an axis-aligned plane keeps its
 * half-space, so that a CSG intersection can cut its box with it. With
 * invert, the bounds of the inverse object (a difference's subtracted
 * children). */
struct aabb object_world_bounds_raw(const struct object *o, bool invert);

#endif

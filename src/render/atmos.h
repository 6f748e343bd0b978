/* atmos.h: the atmosphere applied to rays: the colour of a ray that leaves
 * the scene (background and sky_sphere) and the fogs and rainbows along a
 * ray segment, with POV-Ray 3.7's formulas (measured; see atmos.c). */
#ifndef LUCENT_RENDER_ATMOS_H
#define LUCENT_RENDER_ATMOS_H

#include "render/prepare.h"

/* How far POV-Ray takes a ray that hits nothing to be, for fog and
 * rainbows (measured: a fog of distance 1e11 lets exp(-0.2) of the
 * background through). */
#define ATMOS_MISS_DEPTH 2e10

/* What fog and rainbows need that is decided once: the objects that are
 * not hollow, for POV-Ray's rule that no fog lies inside them. */
struct atmos_ready;

/* Build it from the prepared scene's top-level objects (bounded ones with
 * finite world bounds, and the unbounded ones); the arrays are copied.
 * The caller owns the result (atmos_ready_free). */
struct atmos_ready *atmos_prepare(struct object *const *bounded, size_t nbounded, struct object *const *unbounded,
                                  size_t nunbounded);
void atmos_ready_free(struct atmos_ready *a);

/* The colour seen along unit direction dir where a ray leaves the scene:
 * the sky_sphere's layers (FEAT_SKY) over the background. The rgb is what
 * shows over black (a transparent background adds its colour times
 * 1 - transmit, as POV-Ray does); .t is the share that stays see-through
 * (POV-Ray's alpha is 1 - t with +UA); .f is 0. */
struct rgbft atmos_escape(const struct prepared *p, vec3 dir);

/* Rainbows, then fogs, over the segment of the ray from org along unit
 * direction dir of length depth (ATMOS_MISS_DEPTH for a ray that left the
 * scene), applied to the colour c found at its end. Segments inside a
 * solid (not hollow) object get none, as in POV-Ray. Call only when the
 * scene has FEAT_FOG or FEAT_RAINBOW. */
struct rgbft atmos_apply(const struct prepared *p, vec3 org, vec3 dir, double depth, struct rgbft c);

#endif

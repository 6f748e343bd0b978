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

/* The colour seen along unit direction dir where a ray leaves the scene:
 * the sky_sphere's layers (FEAT_SKY) over the background. The rgb is what
 * shows over black (a transparent background adds its colour times
 * 1 - transmit, as POV-Ray does); .t is the share that stays see-through
 * (POV-Ray's alpha is 1 - t with +UA); .f is 0. */
struct rgbft atmos_escape(const struct prepared *p, vec3 dir);

/* Rainbows, then fogs, over the segment of the ray from org along unit
 * direction dir of length depth (ATMOS_MISS_DEPTH for a ray that left the
 * scene), applied to the colour c found at its end. med is the interiors
 * the ray travels in (NULL: none): as in POV-Ray, a segment inside some
 * object that is not hollow (med->solid) gets none. Call only when the
 * scene has FEAT_FOG or FEAT_RAINBOW. */
struct rgbft atmos_apply(const struct prepared *p, const struct medium *med, vec3 org, vec3 dir, double depth,
                         struct rgbft c);

#endif

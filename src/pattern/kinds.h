/* kinds.h: the raw value of each pattern kind at a pattern-space point q
 * (before frequency, phase and the wave), one function per kind, called by
 * pattern_raw (pattern.c). Internal to src/pattern and texture_eval.c.
 *
 *   noisy.c     agate bozo bumps cells crackle dents granite marble
 *               ripples spotted waves wood wrinkles (and facets' helpers)
 *   geometric.c checker hexagon brick cubic square triangular object boxed
 *               cylindrical spherical planar gradient onion radial spiral1
 *               spiral2 quilted leopard slope aoi function pigment image
 *   fractal.c   julia mandel magnet
 *   tiling.c    tiling
 *   pavement.c  pavement
 */
#ifndef LUCENT_PATTERN_KINDS_H
#define LUCENT_PATTERN_KINDS_H

#include "pattern/pattern.h"

#define PATTERN_FN(name) double pat_##name(const struct pattern *pt, vec3 q, const struct pattern_ctx *ctx)

PATTERN_FN(agate); PATTERN_FN(bozo); PATTERN_FN(bumps); PATTERN_FN(cells); PATTERN_FN(crackle);
PATTERN_FN(dents); PATTERN_FN(facets); PATTERN_FN(granite); PATTERN_FN(marble); PATTERN_FN(ripples);
PATTERN_FN(spotted); PATTERN_FN(waves); PATTERN_FN(wood); PATTERN_FN(wrinkles);

PATTERN_FN(checker); PATTERN_FN(hexagon); PATTERN_FN(brick); PATTERN_FN(cubic); PATTERN_FN(square);
PATTERN_FN(triangular); PATTERN_FN(object); PATTERN_FN(boxed); PATTERN_FN(cylindrical);
PATTERN_FN(spherical); PATTERN_FN(planar); PATTERN_FN(gradient); PATTERN_FN(onion); PATTERN_FN(radial);
PATTERN_FN(spiral1); PATTERN_FN(spiral2); PATTERN_FN(quilted); PATTERN_FN(leopard); PATTERN_FN(slope);
PATTERN_FN(aoi); PATTERN_FN(function); PATTERN_FN(pigment); PATTERN_FN(image);

PATTERN_FN(julia); PATTERN_FN(mandel); PATTERN_FN(magnet);

PATTERN_FN(tiling); PATTERN_FN(pavement);

/* The normal patterns that POV-Ray perturbs with a formula of their own
 * rather than the slope of their value (bumps, dents, ripples, waves,
 * wrinkles, quilted, facets): the perturbed unit normal from the unit normal n at
 * world point p (noisy.c). Returns false for every other kind.
 * n must already face the ray: POV-Ray adds the push to the normal that
 * faces the viewer, along-normal part included, and normalizes. Measured
 * by rendering a plane lit by three coloured parallel lights (16-bit,
 * linear output) and solving for the normal: bumps A gives
 * normalize(n + A·DNoise(q)), dents A normalize(n + A·noise(q)³·DNoise(q)),
 * both within 2e-5 of POV-Ray (the output's quantisation), for generators
 * 1 and 2; wrinkles A normalize(n + A·Σ_i 2^-i |DNoise(2^i q)|) (ten
 * octaves, the absolute value per component); ripples and waves: noisy.c. With transformations the push is added in pattern space: n is
 * carried there as a normal and normalized, the sum carried back
 * (scale <0.5, 1, 1> doubles the push's x, a uniform scale changes
 * nothing, measured). */
bool pattern_special_normal(const struct pattern *pt, double amount, vec3 p, vec3 n,
                            const struct pattern_ctx *ctx, vec3 *out);

#endif

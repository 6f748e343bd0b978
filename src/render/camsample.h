/* camsample.h: what the camera sees at one image position: one ray for a
 * pinhole camera, the lens samples of focal blur, or the rays of a mesh
 * camera's faces. The pixel sampler (render.c: antialiasing) calls this
 * once per sample. */
#ifndef LUCENT_CAMSAMPLE_H
#define LUCENT_CAMSAMPLE_H

#include "render/trace.h"

#include <stdint.h>

/* What focal blur needs, worked out once from the camera: POV-Ray's
 * stopping limits per sample count and the bokeh's sampling table. */
struct lens;

/* The lens of scene s's camera (which must have focal blur on: aperture
 * > 0 and blur_samples_max > 0); a bokeh pigment is sampled here, with
 * the scene's noise settings. The result is owned by the caller
 * (lens_free) and does not refer to s. */
struct lens *lens_new(const struct scene *s);
void lens_free(struct lens *l);

/* The number of lens samples focal blur stops at when every sample has
 * the same colour: the first of POV-Ray's check points at or after the
 * minimum (see camsample.c), or the maximum. For tests. */
int lens_flat_samples(int min, int max);

/* The colour at image position (x, y) (pixels from the top-left corner of
 * a w x h image) for sample number `sample` of pixel (px, py): random
 * choices come from a hash of (px, py, sample, purpose), never from
 * shared state, so images are the same whatever the thread count.
 * *any: an object (not the background) was seen. */
rgb camera_sample(struct tracer *tr, double x, double y, int w, int h, int px, int py, uint32_t sample,
                  bool *any);

#endif

/* camsample.h: what the camera sees at one image position: one ray for a
 * pinhole camera, the lens samples of focal blur otherwise. The pixel
 * sampler (render.c: antialiasing) calls this once per sample. */
#ifndef LUCENT_CAMSAMPLE_H
#define LUCENT_CAMSAMPLE_H

#include "render/trace.h"

#include <stdint.h>

/* The colour at image position (x, y) (pixels from the top-left corner of
 * a w x h image) for sample number `sample` of pixel (px, py): random
 * choices come from a hash of (px, py, sample, purpose), never from
 * shared state, so images are the same whatever the thread count.
 * *any: an object (not the background) was seen. */
rgb camera_sample(struct tracer *tr, double x, double y, int w, int h, int px, int py, uint32_t sample,
                  bool *any);

#endif

/* heightfield.h: the builder API of height_field { ... } (src/geom/
 * heightfield.c): a grid of heights over the unit square, each cell two
 * triangles. doc/objects.md describes the object and how closely it
 * follows POV-Ray. */
#ifndef LUCENT_HEIGHTFIELD_H
#define LUCENT_HEIGHTFIELD_H

#include "scene/object.h"

#include <stdint.h>

/* A height field of w x h samples (w, h >= 2) with the heights v (row
 * major, v[r * w + c]; row 0 is the image's top, at z = 1; column 0 at
 * x = 0): height v / 65536, as POV-Ray keeps them. The grid is copied.
 * The caller owns the result (object_free). */
struct object *heightfield_new(int w, int h, const uint16_t *v, struct srcpos pos);
/* POV-Ray's height of a function value f: the 16-bit value (int)(f *
 * 65535), wrapped to 16 bits (measured: -0.2 gives 0.8). */
uint16_t heightfield_quantize(double f);
void heightfield_set_smooth(struct object *o, bool smooth);
/* Parts of the surface below level (0..1) are not seen. */
void heightfield_set_water_level(struct object *o, double level);
/* hierarchy on|off: only a speed setting (the hits are the same). */
void heightfield_set_hierarchy(struct object *o, bool on);

#endif

/* image.h: images read from files for image_map, bump_map, image_pattern
 * and material_map (PNG, JPEG, TGA, TIFF, OpenEXR, HDR, through the
 * OpenImageIO module), and POV-Ray's ways of laying them on space.
 *
 * Images are cached by path: a scene that names the same file many times
 * reads it once. They are reference-counted. */
#ifndef LUCENT_IMAGE_H
#define LUCENT_IMAGE_H

#include "math/vec.h"
#include "pattern/pattern.h"
#include "scene/color.h"

#include <stdbool.h>

struct image {
	int refs;
	const char *path;            /* owned copy */
	int width, height;
	int channels;                /* as stored in the file: 1 grey, 2 grey+alpha, 3 rgb, 4 rgba */
	float *px;                   /* width*height*4: r g b a, rows top to bottom, linear
	                              * (decoded with the file's or the given gamma) */
	unsigned char *index;        /* palette index per pixel for paletted files (PNG, GIF), else NULL */
	int palette_size;
	bool has_alpha;
};

/* Read the image at path (resolved by the caller). gamma 0: the file's own
 * encoding (sRGB for 8-bit formats unless the file says otherwise, linear
 * for EXR/HDR). On failure returns NULL and writes a message into err. */
struct image *image_load(const char *path, double gamma, char *err, unsigned errsize);
struct image *image_ref(struct image *img);
void image_unref(struct image *img);

/* The image's colour at pattern-space point q laid on as m says (map_type,
 * once, interpolate, filter/transmit overrides). Returns false where the
 * image does not cover q (`once` outside the unit square, the back of a
 * planar map is covered), leaving *out as transparent. If index is not
 * NULL it receives the palette index (or 0). */
bool image_map_eval(const struct image_mapping *m, vec3 q, struct rgbft *out, int *index);
/* A grey value in [0, 1] for image_pattern and bump_map: the colour's
 * intensity, or the alpha with use_alpha, or the palette index / 255. */
double image_map_value(const struct image_mapping *m, vec3 q);

#endif

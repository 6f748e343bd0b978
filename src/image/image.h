/* image.h: images read from files for image_map, bump_map, image_pattern
 * and material_map (PNG read by lucent itself; JPEG, TGA, TIFF, OpenEXR,
 * HDR, GIF, PPM/PGM through the OpenImageIO module), and POV-Ray's ways of
 * laying them on space.
 *
 * Images are cached by path (and decoding): a scene that names the same
 * file many times reads it once. They are reference-counted; the cache
 * holds no reference of its own, so an image leaves it when its last user
 * lets it go. */
#ifndef LUCENT_IMAGE_H
#define LUCENT_IMAGE_H

#include "math/vec.h"
#include "pattern/pattern.h"
#include "scene/color.h"

#include <stdbool.h>

/* image_load's gamma for `gamma srgb`. */
#define IMAGE_GAMMA_SRGB (-1.0)

struct image {
	int refs;
	const char *path;            /* owned copy; NULL for an image made in memory
	                              * (image_from_pixels), which is not cached */
	int width, height;
	int channels;                /* as stored in the file: 1 grey, 2 grey+alpha, 3 rgb, 4 rgba */
	float *px;                   /* width*height*4: r g b a, rows top to bottom, linear
	                              * (decoded with the file's or the given gamma), straight alpha */
	float *raw;                  /* the same as stored in the file (no gamma decoding), for
	                              * image_pattern and bump_map, which read files as data; NULL
	                              * when it equals px */
	unsigned char *index;        /* per pixel: the palette index for paletted files (PNG, GIF,
	                              * colour-mapped TGA), else the stored red value as 0..255
	                              * (what material_map uses) */
	int palette_size;            /* 0 without a palette */
	bool has_alpha;
	double gamma;                /* the decoding asked for (cache key) */
	int premultiplied;           /* the alpha handling asked for (cache key) */
	double working;              /* px's colours are linear^(1/working) (cache key; 1: linear) */
	struct image *next;          /* the cache's list */
};

/* Read the image at path (resolved by the caller). gamma 0: the file's own
 * encoding as POV-Ray 3.7 reads it (PNG: its gAMA chunk, else sRGB; JPEG,
 * GIF, TGA, IFF, BMP: sRGB; PPM, PGM, TIFF: the values as stored; EXR,
 * HDR: linear); gamma > 0: a power law (value^gamma); IMAGE_GAMMA_SRGB:
 * sRGB. premultiplied: -1 the format's own (EXR and TIFF associated, the
 * others straight), 0 straight, 1 associated (colours are divided by
 * alpha). Returns one reference; on failure returns NULL and writes a
 * message into err. */
struct image *image_load(const char *path, double gamma, char *err, unsigned errsize);
struct image *image_load_opts(const char *path, double gamma, int premultiplied, char *err, unsigned errsize);
/* The same with the colours of px carried into a working gamma: the
 * decoded value v becomes v^(1/working) (working 1: none). */
struct image *image_load_working(const char *path, double gamma, int premultiplied, double working, char *err,
                                 unsigned errsize);
/* image_map's colours in the scene's working gamma: POV-Ray 3.7 brings an
 * image_map to the assumed_gamma in force where the image is read (measured:
 * with assumed_gamma 2.2 a pixel decoded to 0.033105 gives 0.212433 =
 * 0.033105^(1/2.2); image_pattern and bump_map are not affected). Replaces
 * m->img by its variant for that working gamma (the file is read again
 * unless the cache has it). false, with a message in err, if that fails. */
bool image_mapping_to_working(struct image_mapping *m, double working, char *err, unsigned errsize);
/* An image made in memory (image_map { function W, H { } }): px holds
 * width*height*4 floats r g b a, rows top to bottom, and becomes the
 * image's; channels as in struct image. Not cached, never re-encoded into a
 * working gamma. Returns one reference, or NULL (px freed) when out of
 * memory. */
struct image *image_from_pixels(int width, int height, int channels, float *px);
struct image *image_ref(struct image *img);
void image_unref(struct image *img);

/* The image's colour at pattern-space point q laid on as m says (map_type,
 * once, interpolate, filter/transmit overrides). Returns false where the
 * image does not cover q (`once` outside the unit square, the axis of a
 * spherical, cylindrical or torus map), leaving *out as POV-Ray's
 * transparent white (1, 1, 1, filter 0, transmit 1). If index is not NULL
 * it receives the index of the pixel q falls in (see struct image; 0 where
 * not covered), for material_map. */
bool image_map_eval(const struct image_mapping *m, vec3 q, struct rgbft *out, int *index);
/* A value in [0, 1] for image_pattern and bump_map, from the file's data
 * (not gamma-decoded unless m->gamma is given): the colour's grey (0.297 r
 * + 0.589 g + 0.114 b), or with use_alpha the transparency 1 - alpha (the
 * red value for files without alpha), or with use_index on a paletted
 * file index / 255. 0 where the image does not cover q. */
double image_map_value(const struct image_mapping *m, vec3 q);

/* The pixel-space point of q (u, v in [0, 1), v up) as m lays the image
 * on space; false where not covered. Exposed for tests. */
bool image_map_uv(const struct image_mapping *m, vec3 q, double *u, double *v);

#endif

/* formats.h: the image formats lucent reads and writes itself, without the
 * OpenImageIO module: PNG (libpng; pngfile.c), TGA and PPM (tgappm.c).
 * Loading OpenImageIO costs about 0.17 s of CPU and 130 MB at every run,
 * more than a small scene's whole render; so these common formats skip it
 * (output.c and image.c choose), and OpenImageIO is loaded only for the
 * others (EXR, HDR, TIFF, JPEG, GIF...).
 *
 * The writers take samples already encoded for the file (output.c: gamma,
 * quantisation and alpha as OpenImageIO's writers stored them) and write
 * them to an open stream; they do not close it. */
#ifndef LUCENT_FORMATS_H
#define LUCENT_FORMATS_H

#include "image/oiio.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Samples ready for a file: width*height*channels values, rows top to
 * bottom, channels r g b [a]; u8 when bits is 8, u16 when it is 16. */
struct img_samples {
	int width, height;
	int channels;        /* 3 or 4 */
	int bits;            /* 8 or 16 */
	const uint8_t *u8;
	const uint16_t *u16;
};

/* Write s as a PNG: 8 or 16 bits, RGB or RGBA, tagged sRGB with the gAMA,
 * sRGB and cHRM chunks (the ones OpenImageIO wrote for lucent) and a
 * Software text. Returns 0, or 1 with a message in err. */
int img_png_write(FILE *fp, const struct img_samples *s, char *err, size_t errsize);
/* Write s (8 bits only) as a TGA: uncompressed (type 2) or run-length
 * encoded (type 10, POV-Ray's +FC), 24 or 32 bits, rows from the top.
 * Returns 0, or 1 with a message in err. */
int img_tga_write(FILE *fp, const struct img_samples *s, bool rle, char *err, size_t errsize);
/* Write the colour channels of s as a binary PPM (P6), maxval 255 or 65535
 * by s->bits (any alpha channel is left out, as POV-Ray does). Returns 0,
 * or 1 with a message in err. */
int img_ppm_write(FILE *fp, const struct img_samples *s, char *err, size_t errsize);

/* Is the file at path a PNG (by its signature)? false if it cannot be read. */
bool img_is_png(const char *path);
/* Read the PNG at path into *out as the OpenImageIO module's oiio_read
 * does (the same channels, samples, palette indices and gamma; see struct
 * oiio_image), so that image maps do not depend on which reader ran.
 * Returns 0; on failure 1 with a message in err and *out empty. */
int img_png_read(const char *path, struct oiio_image *out, char *err, size_t errsize);

#endif

/* output.h: encoding the framebuffer for a file (gamma, bit depth, alpha)
 * and writing it (PNG, TGA and PPM by lucent itself, see formats.h; the
 * other formats through the OpenImageIO module) safely: under a temporary name in the destination folder,
 * renamed into place only when complete, so a failed or interrupted write
 * never destroys an existing image. */
#ifndef LUCENT_OUTPUT_H
#define LUCENT_OUTPUT_H

#include "image/framebuffer.h"

#include <signal.h>
#include <stdbool.h>
#include <stddef.h>

enum img_format { IMG_PNG, IMG_EXR, IMG_HDR, IMG_TGA, IMG_PPM, IMG_JPEG, IMG_TIFF, IMG__COUNT };

struct img_out {
	const char *path;
	enum img_format format;
	int bits;              /* 8 or 16 for integer formats */
	bool alpha;            /* write an alpha channel */
	bool rle;              /* TGA: run-length encoded (POV-Ray's +FC) */
	/* Working gamma of the framebuffer: values are c^gamma in linear light.
	 * gamma <= 0 means POV-Ray's legacy mode (no gamma handling): the
	 * values are written as they are. */
	double gamma;
	/* Checked after the file is complete and before it is renamed: if set,
	 * the temporary file is removed and the write reports interruption. */
	volatile sig_atomic_t *stop;
};

/* The file extension lucent uses for f ("png", "exr", ...). */
const char *img_format_ext(enum img_format f);
/* Guess the format from path's extension; false if unknown. */
bool img_format_from_path(const char *path, enum img_format *f);
/* Write fb. Returns 0 on success, 1 on error (message in err), 2 if
 * interrupted through o->stop. */
int img_write(const struct framebuffer *fb, const struct img_out *o, char *err, size_t errsize);

/* sRGB transfer function: linear [0,1] to encoded. */
double img_srgb_encode(double v);

#endif

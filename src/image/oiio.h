/* oiio.h: the plain C API over OpenImageIO, the only C++ in lucent.
 *
 * OpenImageIO and the libraries it pulls in are large: linked into the
 * program they cost about 0.2 s of dynamic linking at every start and
 * over 100 MB of resident memory. So they live in a module of their own,
 * lucent-oiio.so (src/image/oiio.cc), loaded with dlopen the first time an
 * image is read or written (oiio_load.c). The module is looked for in
 * $LUCENT_OIIO_MODULE, then beside the running program (the build tree),
 * then in the installed package library folder. */
#ifndef LUCENT_OIIO_H
#define LUCENT_OIIO_H

#ifdef __cplusplus
extern "C" {
#endif

enum oiio_type { OIIO_UINT8, OIIO_UINT16, OIIO_FLOAT };

/* The module's entry points (what oiio.cc defines), by name. */
#define OIIO_WRITE_SYMBOL "lucent_oiio_write"
typedef int oiio_write_fn(const char *path, const char *format, int width, int height, int channels,
                          enum oiio_type type, const void *pixels, int srgb, char *err, unsigned errsize);

/* Write pixels (width*height*channels values of `type`, rows top to bottom)
 * to `path` in the format named by `format` ("png", "exr", "tga", ...).
 * `srgb` tags the file as sRGB-encoded where the format can say so.
 * Returns 0 on success; on failure (including a module that cannot be
 * loaded) writes a message into err. */
int oiio_write(const char *path, const char *format, int width, int height, int channels,
               enum oiio_type type, const void *pixels, int srgb, char *err, unsigned errsize);

/* An image as read from a file: the samples as stored (integer formats
 * scaled to [0, 1], nothing decoded), and what the file says about them.
 * px and index are malloc'd and belong to the caller (free()). */
struct oiio_image {
	int width, height;
	int channels;          /* 1 grey, 2 grey+alpha, 3 rgb, 4 rgba (extra channels dropped) */
	float *px;             /* width*height*channels, rows top to bottom */
	unsigned char *index;  /* palette index per pixel for paletted PNG, GIF and
	                        * colour-mapped TGA files; NULL otherwise */
	int palette_size;      /* entries in the palette; 0 without one */
	int bits;              /* bits per sample in the file (8, 16, 32...) */
	int is_float;          /* half or float samples (EXR, HDR, float TIFF) */
	double file_gamma;     /* the decoding gamma the file states (PNG gAMA), else 0 */
	char format[32];       /* OpenImageIO's format name: "png", "openexr", "hdr", ... */
};

#define OIIO_READ_SYMBOL "lucent_oiio_read"
typedef int oiio_read_fn(const char *path, struct oiio_image *out, char *err, unsigned errsize);

/* Read the first image of the file at path, whatever its format (known
 * by its content or extension). OpenImageIO does not tell palette
 * indices, so for paletted files the module reads a second copy of the
 * file whose palette entry i is made the colour (i, 0, 0): the red
 * channel of that copy is the index, exactly, even where two entries
 * have the same colour. Returns 0 on success; on failure (including a
 * module that cannot be loaded) writes a message into err and leaves
 * *out empty. */
int oiio_read(const char *path, struct oiio_image *out, char *err, unsigned errsize);

#ifdef __cplusplus
}
#endif

#endif

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

#ifdef __cplusplus
}
#endif

#endif

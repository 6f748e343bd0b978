/* oiio.h: the plain C API over OpenImageIO, the only C++ in lucent. */
#ifndef LUCENT_OIIO_H
#define LUCENT_OIIO_H

#ifdef __cplusplus
extern "C" {
#endif

enum oiio_type { OIIO_UINT8, OIIO_UINT16, OIIO_FLOAT };

/* Write pixels (width*height*channels values of `type`, rows top to bottom)
 * to `path` in the format named by `format` ("png", "exr", "tga", ...).
 * `srgb` tags the file as sRGB-encoded where the format can say so.
 * Returns 0 on success; on failure writes a message into err. */
int oiio_write(const char *path, const char *format, int width, int height, int channels,
               enum oiio_type type, const void *pixels, int srgb, char *err, unsigned errsize);

#ifdef __cplusplus
}
#endif

#endif

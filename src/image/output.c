/* output.c: encode and write images (see output.h). */
#include "image/output.h"

#include "image/oiio.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

static const char *const exts[IMG__COUNT] = {"png", "exr", "hdr", "tga", "ppm", "jpg", "tif"};

const char *img_format_ext(enum img_format f) { return f < IMG__COUNT ? exts[f] : "png"; }

bool img_format_from_path(const char *path, enum img_format *f)
{
	const char *dot = strrchr(path, '.');
	const char *slash = strrchr(path, '/');
	if (!dot || (slash && dot < slash))
		return false;
	static const struct { const char *ext; enum img_format f; } map[] = {
		{"png", IMG_PNG}, {"exr", IMG_EXR}, {"hdr", IMG_HDR}, {"tga", IMG_TGA},
		{"ppm", IMG_PPM}, {"jpg", IMG_JPEG}, {"jpeg", IMG_JPEG}, {"tif", IMG_TIFF},
		{"tiff", IMG_TIFF},
	};
	for (size_t i = 0; i < sizeof map / sizeof map[0]; i++)
		if (strcasecmp(dot + 1, map[i].ext) == 0) {
			*f = map[i].f;
			return true;
		}
	return false;
}

double img_srgb_encode(double v)
{
	if (v <= 0.0031308)
		return 12.92 * v;
	return 1.055 * pow(v, 1.0 / 2.4) - 0.055;
}

static bool is_float_format(enum img_format f) { return f == IMG_EXR || f == IMG_HDR; }

/* Convert fb into the file's pixel layout; returns a malloc'd buffer. */
static void *encode(const struct framebuffer *fb, const struct img_out *o, int channels, enum oiio_type type)
{
	size_t n = (size_t)fb->width * (size_t)fb->height;
	size_t size = type == OIIO_UINT8 ? 1 : type == OIIO_UINT16 ? 2 : 4;
	unsigned char *buf = malloc(n * (size_t)channels * size);
	if (!buf)
		return NULL;
	double maxv = type == OIIO_UINT8 ? 255.0 : 65535.0;
	for (size_t i = 0; i < n; i++) {
		const float *px = fb->px + i * 4;
		for (int c = 0; c < channels; c++) {
			double v = px[c];
			if (!isfinite(v))
				v = 0;
			if (c < 3 && o->gamma > 0) {
				/* To linear light, then to the file's encoding. */
				if (o->gamma != 1.0)
					v = v > 0 ? pow(v, o->gamma) : 0;
				if (type != OIIO_FLOAT) {
					/* The colour is associated with alpha (what shows over
					 * black); integer files hold it unassociated, as
					 * POV-Ray writes them (measured: PNG bytes of
					 * encode(colour / alpha), clipped at 1). */
					double a = channels == 4 ? fmin(fmax(px[3], 0), 1) : 1;
					if (a < 1)
						v = a > 0 ? v / a : 0;
					v = img_srgb_encode(fmin(fmax(v, 0), 1));
				}
			}
			size_t k = i * (size_t)channels + (size_t)c;
			if (type == OIIO_FLOAT) {
				((float *)buf)[k] = (float)v;
			} else {
				v = fmin(fmax(v, 0), 1);
				long q = lround(v * maxv);
				if (type == OIIO_UINT8)
					buf[k] = (unsigned char)q;
				else
					((uint16_t *)buf)[k] = (uint16_t)q;
			}
		}
	}
	return buf;
}

/* Reserve a unique temporary name beside `path`: "<dir>/.<name>.tmpNNNN.<ext>". */
static char *temp_name(const char *path, const char *ext)
{
	const char *slash = strrchr(path, '/');
	size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
	const char *base = path + dirlen;
	size_t cap = strlen(path) + 64;
	char *t = malloc(cap);
	if (!t)
		return NULL;
	for (int attempt = 0; attempt < 1000; attempt++) {
		snprintf(t, cap, "%.*s.%s.tmp%ld-%d.%s", (int)dirlen, path, base, (long)getpid(), attempt, ext);
		int fd = open(t, O_WRONLY | O_CREAT | O_EXCL, 0644);
		if (fd >= 0) {
			close(fd);
			return t;
		}
		if (errno != EEXIST)
			break;
	}
	free(t);
	return NULL;
}

int img_write(const struct framebuffer *fb, const struct img_out *o, char *err, size_t errsize)
{
	int channels = o->alpha ? 4 : 3;
	enum oiio_type type = is_float_format(o->format) ? OIIO_FLOAT : o->bits == 16 ? OIIO_UINT16 : OIIO_UINT8;
	if (o->format == IMG_HDR)
		channels = 3; /* Radiance HDR has no alpha */
	if (o->format == IMG_JPEG)
		channels = 3;
	const char *ext = img_format_ext(o->format);
	void *pixels = encode(fb, o, channels, type);
	if (!pixels) {
		snprintf(err, errsize, "out of memory encoding a %dx%d image", fb->width, fb->height);
		return 1;
	}
	char *tmp = temp_name(o->path, ext);
	if (!tmp) {
		snprintf(err, errsize, "cannot create a file beside '%s': %s", o->path, strerror(errno));
		free(pixels);
		return 1;
	}
	char msg[512];
	int rc = oiio_write(tmp, ext, fb->width, fb->height, channels, type, pixels,
	                    type != OIIO_FLOAT, msg, sizeof msg);
	free(pixels);
	if (rc != 0) {
		snprintf(err, errsize, "cannot write '%s': %s", o->path, msg);
		unlink(tmp);
		free(tmp);
		return 1;
	}
	if (o->stop && *o->stop) {
		unlink(tmp);
		free(tmp);
		return 2;
	}
	if (rename(tmp, o->path) != 0) {
		snprintf(err, errsize, "cannot write '%s': %s", o->path, strerror(errno));
		unlink(tmp);
		free(tmp);
		return 1;
	}
	free(tmp);
	return 0;
}

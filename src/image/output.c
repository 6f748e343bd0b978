/* output.c: encode and write images (see output.h). */
#include "image/output.h"

#include "image/formats.h"
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

/* Formats lucent writes itself (formats.h); the others go through the
 * OpenImageIO module. */
static bool is_native_format(enum img_format f) { return f == IMG_PNG || f == IMG_TGA || f == IMG_PPM; }

/* One value of pixel px, channel c, in the file's encoding before
 * quantisation: linear light brought to sRGB (unless legacy gamma), or as
 * it is for float files. The framebuffer's colour is associated with
 * alpha (what shows over black); integer files with alpha hold it
 * unassociated, as POV-Ray writes them (measured: PNG bytes of
 * encode(colour / alpha), clipped at 1). */
static double encoded(const float *px, int c, const struct img_out *o, bool is_float, bool has_alpha)
{
	double v = px[c];
	if (!isfinite(v))
		v = 0;
	if (c >= 3)
		return v;
	/* To linear light (unless legacy gamma), then to the file's encoding. */
	if (o->gamma > 0 && o->gamma != 1.0)
		v = v > 0 ? pow(v, o->gamma) : 0;
	if (!is_float) {
		double a = has_alpha && isfinite(px[3]) ? fmin(fmax(px[3], 0), 1) : 1;
		if (a < 1)
			v = a > 0 ? v / a : 0;
		if (o->gamma > 0)
			v = img_srgb_encode(fmin(fmax(v, 0), 1));
	}
	return v;
}

static long quantise(double v, double maxv) { return lround(fmin(fmax(v, 0), 1) * maxv); }

/* Convert fb into the file's pixel layout for the OpenImageIO module;
 * returns a malloc'd buffer. */
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
			double v = encoded(px, c, o, type == OIIO_FLOAT, channels == 4);
			size_t k = i * (size_t)channels + (size_t)c;
			if (type == OIIO_FLOAT)
				((float *)buf)[k] = (float)v;
			else if (type == OIIO_UINT8)
				buf[k] = (unsigned char)quantise(v, maxv);
			else
				((uint16_t *)buf)[k] = (uint16_t)quantise(v, maxv);
		}
	}
	return buf;
}

/* The samples lucent's own writers store (formats.h), exactly as
 * OpenImageIO's writers stored them before, so images did not change when
 * the formats moved out of the module (checked against the module on every
 * 8-bit value/alpha pair and a million 16-bit ones):
 * - colours are quantised to 8 or 16 bits (round to nearest);
 * - a file with alpha gets its colours divided by alpha before they are
 *   encoded (encoded(), as POV-Ray writes them);
 * - TGA holds 8 bits: +F..16 quantises to 16 bits first, then rounds to 8
 *   (floor((v * 255 + 32767) / 65535)).
 * Returns a malloc'd buffer of width*height*channels samples (uint8_t or
 * uint16_t by bits), or NULL when out of memory. */
static void *encode_native(const struct framebuffer *fb, const struct img_out *o, int channels, int bits)
{
	size_t n = (size_t)fb->width * (size_t)fb->height;
	unsigned char *buf = malloc(n * (size_t)channels * (size_t)(bits / 8));
	if (!buf)
		return NULL;
	uint16_t *b16 = (uint16_t *)(void *)buf;
	bool to8 = bits == 8 && o->bits == 16; /* TGA asked for 16 bits */
	uint32_t maxv = bits == 8 ? 255 : 65535;
	for (size_t i = 0; i < n; i++) {
		const float *px = fb->px + i * 4;
		uint32_t q[4];
		for (int c = 0; c < channels; c++) {
			double v = encoded(px, c, o, false, channels == 4);
			if (to8)
				q[c] = ((uint32_t)quantise(v, 65535) * 255 + 32767) / 65535;
			else
				q[c] = (uint32_t)quantise(v, maxv);
		}
		for (int c = 0; c < channels; c++) {
			size_t k = i * (size_t)channels + (size_t)c;
			if (bits == 8)
				buf[k] = (unsigned char)q[c];
			else
				b16[k] = (uint16_t)q[c];
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

/* Write fb to the file tmp with lucent's own writer for o->format.
 * Returns 0, or 1 with a message in err. */
static int write_native(const char *tmp, const struct framebuffer *fb, const struct img_out *o, char *err,
                        size_t errsize)
{
	/* PPM has no alpha channel (POV-Ray leaves it out too); TGA only 8 bits. */
	int channels = o->alpha && o->format != IMG_PPM ? 4 : 3;
	int bits = o->format != IMG_TGA && o->bits == 16 ? 16 : 8;
	void *px = encode_native(fb, o, channels, bits);
	if (!px) {
		snprintf(err, errsize, "out of memory encoding a %dx%d image", fb->width, fb->height);
		return 1;
	}
	FILE *fp = fopen(tmp, "wb");
	if (!fp) {
		snprintf(err, errsize, "%s", strerror(errno));
		free(px);
		return 1;
	}
	struct img_samples s = {
		.width = fb->width, .height = fb->height, .channels = channels, .bits = bits,
		.u8 = bits == 8 ? px : NULL, .u16 = bits == 16 ? px : NULL,
	};
	int rc = o->format == IMG_PNG   ? img_png_write(fp, &s, err, errsize)
	         : o->format == IMG_TGA ? img_tga_write(fp, &s, o->rle, err, errsize)
	                                : img_ppm_write(fp, &s, err, errsize);
	if (ferror(fp) && rc == 0) {
		snprintf(err, errsize, "write failed");
		rc = 1;
	}
	if (fclose(fp) != 0 && rc == 0) {
		snprintf(err, errsize, "%s", strerror(errno));
		rc = 1;
	}
	free(px);
	return rc;
}

/* Write fb to the file tmp through the OpenImageIO module. Returns 0, or 1
 * with a message in err. */
static int write_oiio(const char *tmp, const struct framebuffer *fb, const struct img_out *o, char *err,
                      size_t errsize)
{
	int channels = o->alpha ? 4 : 3;
	enum oiio_type type = is_float_format(o->format) ? OIIO_FLOAT : o->bits == 16 ? OIIO_UINT16 : OIIO_UINT8;
	if (o->format == IMG_HDR)
		channels = 3; /* Radiance HDR has no alpha */
	if (o->format == IMG_JPEG)
		channels = 3;
	void *pixels = encode(fb, o, channels, type);
	if (!pixels) {
		snprintf(err, errsize, "out of memory encoding a %dx%d image", fb->width, fb->height);
		return 1;
	}
	int rc = oiio_write(tmp, img_format_ext(o->format), fb->width, fb->height, channels, type, pixels,
	                    type != OIIO_FLOAT, err, (unsigned)errsize);
	free(pixels);
	return rc;
}

int img_write(const struct framebuffer *fb, const struct img_out *o, char *err, size_t errsize)
{
	char *tmp = temp_name(o->path, img_format_ext(o->format));
	if (!tmp) {
		snprintf(err, errsize, "cannot create a file beside '%s': %s", o->path, strerror(errno));
		return 1;
	}
	char msg[512];
	int rc = is_native_format(o->format) ? write_native(tmp, fb, o, msg, sizeof msg)
	                                     : write_oiio(tmp, fb, o, msg, sizeof msg);
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

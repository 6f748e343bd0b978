/* test_formats.c: unit tests for the images lucent writes and reads itself
 * (src/image/output.c, pngfile.c, tgappm.c).
 *
 * The rule is that nothing changed when PNG, TGA and PPM moved out of the
 * OpenImageIO module: the samples written are the ones the module wrote,
 * and a PNG read gives what the module's reader gives. The expected
 * samples below were measured by writing through the module
 * (lucent_oiio_write of the build before the change, with the same
 * quantised input) and reading the files' bytes; the readers are checked
 * against the module directly. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "image/formats.h"
#include "image/framebuffer.h"
#include "image/oiio.h"
#include "image/output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[4096];
static char tmpdir[256];

static void setup_paths(void)
{
	const char *top = getenv("top_srcdir");
	snprintf(dir, sizeof dir, "%s/tests/data/images", top ? top : ".");
	const char *lucent = getenv("LUCENT");
	if (lucent && !getenv("LUCENT_OIIO_MODULE")) {
		char mod[4096];
		snprintf(mod, sizeof mod, "%s", lucent);
		char *slash = strrchr(mod, '/');
		if (slash) {
			snprintf(slash + 1, sizeof mod - (size_t)(slash + 1 - mod), "lucent-oiio.so");
			setenv("LUCENT_OIIO_MODULE", mod, 1);
		}
	}
	snprintf(tmpdir, sizeof tmpdir, "/tmp/lucent-test-formats-XXXXXX");
	if (!mkdtemp(tmpdir))
		abort();
}

/* Every (value, alpha) pair of 8-bit samples, one pixel each: pixel
 * (x = v, y = a) has colour (v, v, 255 - v) / 255 and alpha a / 255.
 * Written with gamma 0 (no gamma handling), the quantised samples are
 * exactly v and a. */
static struct framebuffer *pairs(void)
{
	struct framebuffer *fb = fb_new(256, 256);
	for (int a = 0; a < 256; a++)
		for (int v = 0; v < 256; v++) {
			float *p = fb_pixel(fb, v, a);
			p[0] = p[1] = (float)(v / 255.0);
			p[2] = (float)((255 - v) / 255.0);
			p[3] = (float)(a / 255.0);
		}
	return fb;
}

static char *tmp_path(const char *name)
{
	static char path[512];
	snprintf(path, sizeof path, "%s/%s", tmpdir, name);
	return path;
}

static void write_fb(const struct framebuffer *fb, const char *path, enum img_format f, int bits, bool alpha,
                     bool rle)
{
	struct img_out o = {.path = path, .format = f, .bits = bits, .alpha = alpha, .rle = rle, .gamma = 0};
	char err[512];
	if (img_write(fb, &o, err, sizeof err) != 0)
		fail_msg("%s", err);
}

/* The colour sample stored for 8-bit value v under alpha a: files hold
 * colours unassociated, divided by alpha before they are quantised, as
 * POV-Ray writes them (measured with +UA: the PNG bytes are
 * encode(colour / alpha), clipped at 1); under alpha 0 the colour is 0.
 * Computed from the framebuffer's float samples as the writer sees them:
 * a = 2, v = 1 -> 128; a = 4, v = 1 -> 64; v >= a -> 255. */
static unsigned straight8(unsigned v, unsigned a)
{
	if (a == 0)
		return 0;
	double x = (double)(float)(v / 255.0) / (double)(float)(a / 255.0);
	return (unsigned)lround(fmin(x, 1) * 255);
}

/* PNG with alpha: every pair, read back with the OpenImageIO module's
 * reader (independent of lucent's own). */
static void test_png_alpha_pairs(void **state)
{
	(void)state;
	struct framebuffer *fb = pairs();
	char *path = tmp_path("pairs.png");
	write_fb(fb, path, IMG_PNG, 8, true, false);
	struct oiio_image o;
	char err[512];
	if (oiio_read(path, &o, err, sizeof err) != 0)
		fail_msg("%s", err);
	assert_int_equal(o.channels, 4);
	assert_int_equal(o.bits, 8);
	assert_true(o.file_gamma == 0); /* tagged sRGB */
	assert_int_equal((int)(o.px[(2 * 256 + 1) * 4] * 255 + 0.5), 128);
	assert_int_equal((int)(o.px[(4 * 256 + 1) * 4] * 255 + 0.5), 64);
	int bad = 0;
	for (unsigned a = 0; a < 256; a++)
		for (unsigned v = 0; v < 256; v++) {
			const float *p = &o.px[(a * 256 + v) * 4];
			unsigned r = (unsigned)(p[0] * 255 + 0.5f), b = (unsigned)(p[2] * 255 + 0.5f);
			unsigned al = (unsigned)(p[3] * 255 + 0.5f);
			bad += r != straight8(v, a) || b != straight8(255 - v, a) || al != a;
		}
	assert_int_equal(bad, 0);
	free(o.px);
	free(o.index);
	unlink(path);
	fb_free(fb);
}

/* 16-bit PNG: samples round(v * 65535); with alpha round(v / a * 65535). */
static void test_png16(void **state)
{
	(void)state;
	struct framebuffer *fb = fb_new(3, 1);
	float *p = fb_pixel(fb, 0, 0);
	p[0] = 0.25f, p[1] = 0.5f, p[2] = 1.0f, p[3] = 1;
	p = fb_pixel(fb, 1, 0);
	p[0] = 0.1f, p[1] = 0.0f, p[2] = 0.3f, p[3] = 0.5f;
	p = fb_pixel(fb, 2, 0);
	p[0] = 0.7f, p[1] = 2.0f, p[2] = -1.0f, p[3] = 0.0f;
	char *path = tmp_path("b16.png");
	write_fb(fb, path, IMG_PNG, 16, true, false);
	struct oiio_image o;
	char err[512];
	if (img_png_read(path, &o, err, sizeof err) != 0)
		fail_msg("%s", err);
	assert_int_equal(o.bits, 16);
	assert_int_equal(o.channels, 4);
	unsigned want[12] = {16384, 32768, 65535, 65535,
	                     /* 0.1 / 0.5 -> 13107, 0.3 / 0.5 -> 39321 */
	                     13107, 0, 39321, 32768,
	                     /* alpha 0: no colour */
	                     0, 0, 0, 0};
	for (int k = 0; k < 12; k++)
		assert_int_equal((unsigned)(o.px[k] * 65535 + 0.5f), want[k]);
	free(o.px);
	unlink(path);
	fb_free(fb);
}

/* TGA, uncompressed and run-length encoded (+FC): the module reads both
 * back the same, with the alpha rule of PNG; asking for 16 bits rounds the
 * 16-bit samples to 8 (floor((q * 255 + 32767) / 65535)). */
static void test_tga(void **state)
{
	(void)state;
	struct framebuffer *fb = pairs();
	/* Runs for the encoder: a row of one colour, a row of pairs. */
	for (int v = 0; v < 256; v++) {
		float *p = fb_pixel(fb, v, 255);
		p[0] = p[1] = p[2] = 0.5f;
		p = fb_pixel(fb, v, 254);
		p[0] = p[1] = p[2] = (float)((v / 2) / 255.0);
	}
	char raw[512], rle[512];
	snprintf(raw, sizeof raw, "%s", tmp_path("raw.tga"));
	snprintf(rle, sizeof rle, "%s", tmp_path("rle.tga"));
	for (int alpha = 0; alpha < 2; alpha++) {
		write_fb(fb, raw, IMG_TGA, 8, alpha, false);
		write_fb(fb, rle, IMG_TGA, 8, alpha, true);
		struct oiio_image a, b;
		char err[512];
		if (oiio_read(raw, &a, err, sizeof err) != 0 || oiio_read(rle, &b, err, sizeof err) != 0)
			fail_msg("%s", err);
		assert_int_equal(a.channels, alpha ? 4 : 3);
		assert_int_equal(b.channels, a.channels);
		assert_memory_equal(a.px, b.px, sizeof(float) * 256 * 256 * (size_t)a.channels);
		if (alpha)
			for (unsigned al = 0; al < 254; al += 7)
				for (unsigned v = 0; v < 256; v += 3)
					assert_int_equal((unsigned)(a.px[(al * 256 + v) * 4] * 255 + 0.5f), straight8(v, al));
		free(a.px);
		free(b.px);
		FILE *fp = fopen(rle, "rb");
		unsigned char h[18];
		assert_int_equal(fread(h, 1, 18, fp), 18);
		fclose(fp);
		assert_int_equal(h[2], 10);
		assert_int_equal(h[16], alpha ? 32 : 24);
	}
	/* 16 bits asked: the samples are rounded to 16 bits, then to 8. */
	struct framebuffer *one = fb_new(1, 1);
	float *p = fb_pixel(one, 0, 0);
	p[0] = 0.3f, p[1] = 0.50196f, p[2] = 0.00196f, p[3] = 1;
	write_fb(one, raw, IMG_TGA, 16, false, false);
	FILE *fp = fopen(raw, "rb");
	unsigned char d[21];
	assert_int_equal(fread(d, 1, 21, fp), 21);
	fclose(fp);
	assert_int_equal(d[18 + 2], (19661 * 255 + 32767) / 65535);
	assert_int_equal(d[18 + 1], (32896 * 255 + 32767) / 65535);
	assert_int_equal(d[18 + 0], (128 * 255 + 32767) / 65535);
	unlink(raw);
	unlink(rle);
	fb_free(one);
	fb_free(fb);
}

/* PPM: P6 with maxval 255, or 65535 for +FP16 as POV-Ray writes it; any
 * alpha is left out. */
static void test_ppm(void **state)
{
	(void)state;
	struct framebuffer *fb = fb_new(2, 1);
	float *p = fb_pixel(fb, 0, 0);
	p[0] = 0.25f, p[1] = 0.5f, p[2] = 1.0f, p[3] = 0.5f;
	p = fb_pixel(fb, 1, 0);
	p[0] = 0.0f, p[1] = 0.75f, p[2] = 0.125f, p[3] = 1;
	char *path = tmp_path("a.ppm");
	write_fb(fb, path, IMG_PPM, 8, true, false);
	FILE *fp = fopen(path, "rb");
	unsigned char d[64];
	size_t n = fread(d, 1, sizeof d, fp);
	fclose(fp);
	assert_int_equal(n, 11 + 6);
	assert_memory_equal(d, "P6\n2 1\n255\n", 11);
	unsigned char want8[6] = {64, 128, 255, 0, 191, 32};
	assert_memory_equal(d + 11, want8, 6);
	write_fb(fb, path, IMG_PPM, 16, false, false);
	fp = fopen(path, "rb");
	n = fread(d, 1, sizeof d, fp);
	fclose(fp);
	assert_int_equal(n, 13 + 12);
	assert_memory_equal(d, "P6\n2 1\n65535\n", 13);
	unsigned char want16[12] = {0x40, 0x00, 0x80, 0x00, 0xff, 0xff, 0, 0, 0xbf, 0xff, 0x20, 0x00};
	assert_memory_equal(d + 13, want16, 12);
	unlink(path);
	fb_free(fb);
}

/* The PNG chunks: gAMA 45455, sRGB (intent 3), cHRM, as the module wrote. */
static void test_png_chunks(void **state)
{
	(void)state;
	struct framebuffer *fb = fb_new(1, 1);
	char *path = tmp_path("c.png");
	write_fb(fb, path, IMG_PNG, 8, false, false);
	FILE *fp = fopen(path, "rb");
	unsigned char d[4096];
	size_t n = fread(d, 1, sizeof d, fp);
	fclose(fp);
	bool gama = false, srgb = false, chrm = false;
	for (size_t at = 8; at + 12 <= n;) {
		size_t len = (size_t)d[at] << 24 | (size_t)d[at + 1] << 16 | (size_t)d[at + 2] << 8 | d[at + 3];
		const unsigned char *t = d + at + 4, *b = d + at + 8;
		if (!memcmp(t, "gAMA", 4))
			gama = len == 4 && b[0] == 0 && b[1] == 0 && b[2] == 0xb1 && b[3] == 0x8f;
		if (!memcmp(t, "sRGB", 4))
			srgb = len == 1 && b[0] == 3;
		if (!memcmp(t, "cHRM", 4))
			chrm = len == 32;
		at += 12 + len;
	}
	assert_true(gama && srgb && chrm);
	unlink(path);
	fb_free(fb);
}

/* Reading: lucent's PNG reader gives exactly what the module's gives, on
 * every PNG of tests/data/images (grey, grey+alpha, RGB, RGBA, 16-bit,
 * paletted with tRNS, gAMA 1.0). */
static void test_png_read_as_module(void **state)
{
	(void)state;
	static const char *names[] = {"rgb.png", "rgb16.png", "grey.png", "greya.png", "rgba.png", "pal.png", "gamma1.png"};
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
		char path[4200], err[512];
		snprintf(path, sizeof path, "%s/%s", dir, names[i]);
		assert_true(img_is_png(path));
		struct oiio_image a, b;
		if (oiio_read(path, &a, err, sizeof err) != 0 || img_png_read(path, &b, err, sizeof err) != 0)
			fail_msg("%s: %s", names[i], err);
		assert_int_equal(a.width, b.width);
		assert_int_equal(a.height, b.height);
		assert_int_equal(a.channels, b.channels);
		assert_int_equal(a.bits, b.bits);
		assert_int_equal(a.palette_size, b.palette_size);
		assert_true(a.file_gamma == b.file_gamma);
		assert_string_equal(a.format, b.format);
		assert_memory_equal(a.px, b.px, sizeof(float) * (size_t)a.width * a.height * (size_t)a.channels);
		assert_int_equal(!a.index, !b.index);
		if (a.index)
			assert_memory_equal(a.index, b.index, (size_t)a.width * a.height);
		free(a.px), free(a.index), free(b.px), free(b.index);
	}
	char path[4200], err[512];
	snprintf(path, sizeof path, "%s/rgb.tga", dir);
	assert_false(img_is_png(path));
	snprintf(path, sizeof path, "%s/make.py", dir);
	struct oiio_image b;
	assert_int_equal(img_png_read(path, &b, err, sizeof err), 1);
	assert_null(b.px);
}

int main(void)
{
	setup_paths();
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_png_alpha_pairs), cmocka_unit_test(test_png16),
		cmocka_unit_test(test_tga),             cmocka_unit_test(test_ppm),
		cmocka_unit_test(test_png_chunks),      cmocka_unit_test(test_png_read_as_module),
	};
	int rc = cmocka_run_group_tests(tests, NULL, NULL);
	rmdir(tmpdir);
	return rc;
}

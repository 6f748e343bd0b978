/* test_image.c: unit tests for images (src/image/image.c, the OpenImageIO
 * module's reading) and the image blocks' parsing (src/lang/image_parse.c).
 *
 * The images are in tests/data/images (written by make.py there). Every
 * expected value was measured with POV-Ray 3.7.0.10 by evaluating the
 * pigment or pattern as a function and printing it, e.g.
 *   #version 3.7;
 *   global_settings { assumed_gamma 1.0 }
 *   #declare F = function { pigment { image_map { png "rgb.png" gamma 1.0 } } }
 *   #local c = F(0.25, 0.5, 0);
 *   #debug concat(str(c.red*255,0,2), " ", str(c.green*255,0,2), " ",
 *                 str(c.blue*255,0,2), " f", str(c.filter,0,3), " t", str(c.transmit,0,3), "\n")
 * (the same values a plane with the image_map at ambient 1, diffuse 0
 * shows). Values are quoted as POV-Ray printed them (0..255 scale for
 * colours). rgb.png is 4 x 2: pixel (column c, row r from the top) is
 * (60c + 10, 100r + 20, 200 - 40c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "image/image.h"
#include "image/oiio.h"
#include "lang/parser.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testutil.h"

static char dir[4096];

static void setup_paths(void)
{
	const char *top = getenv("top_srcdir");
	snprintf(dir, sizeof dir, "%s/tests/data/images", top ? top : ".");
	/* The module sits beside the lucent program in the build tree. */
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
}

static struct image *load(const char *name, double gamma)
{
	char path[4200], err[512];
	snprintf(path, sizeof path, "%s/%s", dir, name);
	struct image *img = image_load(path, gamma, err, sizeof err);
	if (!img)
		fail_msg("%s", err);
	return img;
}

static struct image_mapping mapping(struct image *img)
{
	return (struct image_mapping){.img = img, .premultiplied = -1};
}

/* The colour at (x, y, z) on POV-Ray's 0..255 scale, and f, t. */
#define assert_at(m, x, y, z, er, eg, eb, ef, et, tol)                          \
	do {                                                                    \
		struct rgbft c_;                                                \
		image_map_eval(&(m), v3(x, y, z), &c_, NULL);                   \
		assert_near(c_.r * 255, er, tol);                               \
		assert_near(c_.g * 255, eg, tol);                               \
		assert_near(c_.b * 255, eb, tol);                               \
		assert_near(c_.f, ef, 0.0005);                                  \
		assert_near(c_.t, et, 0.0005);                                  \
	} while (0)

/* Planar: column floor(x * 4), row from the bottom floor(y * 2), the
 * unit square repeated. POV-Ray: (0.01, 0.01) gives pixel (0, 1);
 * (0.2499999, y) column 0, (0.25, y) column 1; (0, 0.4999999) row 1,
 * (0, 0.5) row 0; (-0.01, 0.01) column 3 (wrapped); (1, 1) = (0, 0). */
static void test_planar_addressing(void **state)
{
	(void)state;
	struct image *img = load("rgb.png", 1.0);
	struct image_mapping m = mapping(img);
	assert_at(m, 0.01, 0.01, 0, 10, 120, 200, 0, 0, 1e-4);
	assert_at(m, 0.2499999, 0.01, 0, 10, 120, 200, 0, 0, 1e-4);
	assert_at(m, 0.25, 0.01, 0, 70, 120, 160, 0, 0, 1e-4);
	assert_at(m, 0, 0.4999999, 0, 10, 120, 200, 0, 0, 1e-4);
	assert_at(m, 0, 0.5, 0, 10, 20, 200, 0, 0, 1e-4);
	assert_at(m, -0.01, 0.01, 0, 190, 120, 80, 0, 0, 1e-4);
	assert_at(m, 1, 1, 0, 10, 120, 200, 0, 0, 1e-4);
	assert_at(m, 0.99, 0.99, 7, 190, 20, 80, 0, 0, 1e-4);
	/* once: (1, 1) and (0, 0) are inside (pixel (0, 1)); (-0.001, 0.5) and
	 * (0.5, -0.0001) give POV-Ray's transparent white. */
	m.once = true;
	assert_at(m, 1, 1, 0, 10, 120, 200, 0, 0, 1e-4);
	assert_at(m, 1, 0.5, 0, 10, 20, 200, 0, 0, 1e-4);
	assert_at(m, -0.001, 0.5, 0, 255, 255, 255, 0, 1, 1e-4);
	assert_at(m, 0.5, -0.0001, 5, 255, 255, 255, 0, 1, 1e-4);
	image_unref(img);
}

/* sRGB decoding of an 8-bit PNG with no gAMA: POV-Ray (no gamma given):
 * pixel (0, 1) -> 0.003035 0.187821 0.577581; (3, 0) -> 0.514918 0.006995
 * 0.080220. gamma 2.2: pixel (0, 0) 0.21 0.94 149.42; gamma srgb: 0.77
 * 1.78 147.28. */
static void test_gamma(void **state)
{
	(void)state;
	struct image *img = load("rgb.png", 0);
	struct image_mapping m = mapping(img);
	assert_at(m, 0.01, 0.01, 0, 0.003035 * 255, 0.187821 * 255, 0.577581 * 255, 0, 0, 1e-3);
	assert_at(m, 0.99, 0.99, 0, 0.514918 * 255, 0.006995 * 255, 0.080220 * 255, 0, 0, 1e-3);
	image_unref(img);
	img = load("rgb.png", 2.2);
	m = mapping(img);
	assert_at(m, 0.125, 0.75, 0, 0.21, 255 - 254.06, 149.42, 0, 0, 0.01);
	image_unref(img);
	img = load("rgb.png", IMAGE_GAMMA_SRGB);
	m = mapping(img);
	assert_at(m, 0.125, 0.75, 0, 0.77, 255 - 253.22, 147.28, 0, 0, 0.01);
	image_unref(img);
	/* A gAMA chunk of 1.0: 128 stays 128. */
	img = load("gamma1.png", 0);
	m = mapping(img);
	assert_at(m, 0.25, 0.5, 0, 128, 128, 128, 0, 0, 1e-3);
	image_unref(img);
	/* PPM, PGM, TIFF: as stored (POV-Ray: 130 20 120 at (0.5, 0.5) under
	 * assumed_gamma 1). TGA: sRGB like PNG (56.92 1.78 47.89). */
	img = load("rgb.ppm", 0);
	m = mapping(img);
	assert_at(m, 0.5, 0.5, 0, 130, 20, 120, 0, 0, 1e-3);
	image_unref(img);
	img = load("rgb.tif", 0);
	m = mapping(img);
	assert_at(m, 0.5, 0.5, 0, 130, 20, 120, 0, 0, 1e-3);
	image_unref(img);
	img = load("grey.pgm", 0);
	m = mapping(img);
	assert_at(m, 0.5, 0.5, 0, 128, 128, 128, 0, 0, 1e-3);
	image_unref(img);
	img = load("rgb.tga", 0);
	m = mapping(img);
	assert_at(m, 0.5, 0.5, 0, 56.92, 255 - 253.22, 47.89, 0, 0, 0.01);
	image_unref(img);
	/* 16-bit PNG, sRGB: 0x1234 -> 1.56; EXR linear (0.25 -> 63.75, and
	 * values above 1 kept: 4 -> 1020), gamma on an EXR applies (2.2: 12.08). */
	img = load("rgb16.png", 0);
	m = mapping(img);
	assert_at(m, 0.25, 0.5, 0, 1.56, 255 - 200.42, 255, 0, 0, 0.01);
	image_unref(img);
	img = load("float.exr", 0);
	m = mapping(img);
	assert_at(m, 0.25, 0.5, 0, 63.75, 255 + 127.5, 1020, 0, 0, 1e-3);
	image_unref(img);
	img = load("float.exr", 2.2);
	m = mapping(img);
	assert_at(m, 0.25, 0.5, 0, 12.08, 255 + 367.22, 5383.59, 0, 0, 0.01);
	image_unref(img);
}

/* Interpolation on rgb.png (gamma 1.0), POV-Ray along y = 0.75 (row 0):
 *   interpolate 2 at x = 0, 0.0625, 0.25, 0.9375: R 100 55 40 145
 *   interpolate 4 at x = 0, 0.0625: R 100 32.48, G 36.67 28.17
 *   interpolate 3 at x = 0.0625, 0.1875, 0.25, 0.6875: R 43.75 8.125 25 150.63
 * and along x = 0.125: interpolate 2 at y = 0, 0.125: G 70 95;
 * interpolate 4 at y = 0.125: R 14.90 G 107.51. */
static void test_interpolation(void **state)
{
	(void)state;
	struct image *img = load("rgb.png", 1.0);
	struct image_mapping m = mapping(img);
	m.interpolate = 2;
	assert_at(m, 0, 0.75, 0, 100, 20, 140, 0, 0, 1e-3);
	assert_at(m, 0.0625, 0.75, 0, 55, 20, 170, 0, 0, 1e-3);
	assert_at(m, 0.25, 0.75, 0, 40, 20, 180, 0, 0, 1e-3);
	assert_at(m, 0.9375, 0.75, 0, 145, 20, 110, 0, 0, 1e-3);
	assert_at(m, 0.125, 0, 0, 10, 70, 200, 0, 0, 1e-3);
	assert_at(m, 0.125, 0.125, 0, 10, 95, 200, 0, 0, 1e-3);
	m.interpolate = 4;
	assert_at(m, 0, 0.75, 0, 100, 0.143791 * 255, 140, 0, 0, 1e-3);
	assert_at(m, 0.0625, 0.75, 0, 0.127375 * 255, 0.110461 * 255, 0.725541 * 255, 0, 0, 1e-3);
	assert_at(m, 0.125, 0.125, 0, 0.058434 * 255, 0.421611 * 255, 0.771502 * 255, 0, 0, 1e-3);
	assert_at(m, 0.125, 0.75, 0, 10, 20, 200, 0, 0, 1e-3);
	m.interpolate = 3;
	assert_at(m, 0.0625, 0.75, 0, 0.171569 * 255, 20, 0.696078 * 255, 0, 0, 1e-3);
	assert_at(m, 0.1875, 0.75, 0, 0.031863 * 255, 20, 0.789216 * 255, 0, 0, 1e-3);
	assert_at(m, 0.25, 0.75, 0, 0.098039 * 255, 20, 0.745098 * 255, 0, 0, 1e-3);
	assert_at(m, 0.6875, 0.75, 0, 0.590686 * 255, 20, 0.416667 * 255, 0, 0, 1e-3);
	/* once clamps at the edges: interpolate 2 at (0.01, 0.75) is pixel
	 * (0, 0); interpolate 4 at (0.125, 0.99): 19.96 20 193.36; interpolate
	 * 3 at (0.01, 0.75): 5.98 20 202.68, at (0.125, 0.99): G 13.51. */
	m.once = true;
	m.interpolate = 2;
	assert_at(m, 0.01, 0.75, 0, 10, 20, 200, 0, 0, 1e-3);
	assert_at(m, 0.99, 0.75, 0, 190, 20, 80, 0, 0, 1e-3);
	m.interpolate = 4;
	assert_at(m, 0.125, 0.99, 0, 19.96, 20, 193.36, 0, 0, 0.01);
	m.interpolate = 3;
	assert_at(m, 0.01, 0.75, 0, 5.98, 20, 202.68, 0, 0, 0.01);
	assert_at(m, 0.125, 0.99, 0, 10, 255 - 241.49, 200, 0, 0, 0.01);
	image_unref(img);
}

/* uv.png is 256 x 256 with pixel (c, r) = (c, r, 0): POV-Ray printed
 * floor(u * 256) and floor(v * 256) for each map type. */
static void test_map_types(void **state)
{
	(void)state;
	struct image_mapping m = {.premultiplied = -1};
	double u, v;
	static const struct { int type; bool once; double x, y, z; int cu, cv; } pts[] = {
		{1, 0, 1, 0, 0, 0, 128}, {1, 0, 0, 0, 1, 64, 128}, {1, 0, -1, 0, 0, 128, 128},
		{1, 0, 0, 0, -1, 192, 128}, {1, 0, 1, 1, 0, 0, 192}, {1, 0, 0.3, 0.5, 0.2, 23, 205},
		{1, 0, 0.3, -0.5, -0.2, 232, 50}, {1, 0, 0, 1, 0, 0, 0}, {1, 0, 0, -1, 0, 0, 0},
		{1, 0, 2, 0.001, 2, 32, 128},
		{2, 0, 1, 0, 0, 0, 0}, {2, 0, 0, 0, 1, 64, 0}, {2, 0, 0.3, 0.5, 0.2, 23, 128},
		{2, 0, 0.3, 1.5, -0.2, 232, 128}, {2, 0, 0.3, -0.3, -0.2, 232, 179}, {2, 1, 1, 1, 0, 0, 0},
		{5, 0, 1.5, 0, 0, 0, 128}, {5, 0, 0.5, 0, 0, 0, 0}, {5, 0, 1, 0.5, 0, 0, 192},
		{5, 0, 1, -0.5, 0, 0, 64}, {5, 0, 0, 0, 1.5, 64, 128}, {5, 0, 0.3, 0.2, 1.1, 53, 167},
		{5, 0, -0.7, -0.2, -0.9, 165, 88}, {5, 0, 3, 0, 0, 0, 128},
	};
	for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++) {
		m.map_type = pts[i].type;
		m.once = pts[i].once;
		assert_true(image_map_uv(&m, v3(pts[i].x, pts[i].y, pts[i].z), &u, &v));
		if ((int)(u * 256) != pts[i].cu || (int)(v * 256) != pts[i].cv)
			fail_msg("map_type %d at (%g, %g, %g): %d %d, POV-Ray %d %d", pts[i].type, pts[i].x, pts[i].y,
			         pts[i].z, (int)(u * 256), (int)(v * 256), pts[i].cu, pts[i].cv);
	}
	/* Not covered (POV-Ray: transparent white): the sphere's centre, the
	 * cylinder's and torus's axis, a once cylinder outside 0 <= y <= 1. */
	m.once = false;
	m.map_type = 1;
	assert_false(image_map_uv(&m, v3(0, 0, 0), &u, &v));
	m.map_type = 2;
	assert_false(image_map_uv(&m, v3(0, 0.5, 0), &u, &v));
	m.map_type = 5;
	assert_false(image_map_uv(&m, v3(0, 0, 0), &u, &v));
	m.map_type = 2;
	m.once = true;
	assert_false(image_map_uv(&m, v3(0.3, 1.5, -0.2), &u, &v));
	assert_false(image_map_uv(&m, v3(0.3, -0.3, -0.2), &u, &v));
}

/* Alpha: rgba.png is (255 0 0 a 255), (0 200 100 a 51): POV-Ray gives
 * transmit 0 and 0.8; with `transmit all 0.5 filter all 0.25`: f 0.25,
 * t 0.5 and 1.3 (added to the alpha's); premultiplied on: 0 1000 500.
 * greya.png pixel 1 (100, alpha 64): t 0.749. */
static void test_alpha(void **state)
{
	(void)state;
	struct image *img = load("rgba.png", 1.0);
	struct image_mapping m = mapping(img);
	assert_at(m, 0.25, 0.5, 0, 255, 0, 0, 0, 0, 1e-3);
	assert_at(m, 0.75, 0.5, 0, 0, 200, 100, 0, 0.8, 1e-3);
	m.has_transmit_all = m.has_filter_all = true;
	m.transmit_all = 0.5;
	m.filter_all = 0.25;
	assert_at(m, 0.25, 0.5, 0, 255, 0, 0, 0.25, 0.5, 1e-3);
	assert_at(m, 0.75, 0.5, 0, 0, 200, 100, 0.25, 1.3, 1e-3);
	image_unref(img);
	char path[4200], err[256];
	snprintf(path, sizeof path, "%s/rgba.png", dir);
	img = image_load_opts(path, 1.0, 1, err, sizeof err);
	assert_non_null(img);
	m = mapping(img);
	assert_at(m, 0.75, 0.5, 0, 0, 1000, 500, 0, 0.8, 1e-2);
	image_unref(img);
	img = load("greya.png", 1.0);
	m = mapping(img);
	assert_at(m, 0.75, 0.5, 0, 100, 100, 100, 0, 0.749, 1e-3);
	image_unref(img);
}

/* Palettes: pal.png and pal.gif are 4 x 2 with indices (0 1 2 3 / 4 5 0
 * 1) into red, green, blue, yellow, green (again), (40 80 120); PNG tRNS
 * gives entry 0 alpha 128 and entry 2 alpha 0; the GIF's transparent
 * index is 2. POV-Ray, pal.png: t 0.498 at index 0, 1.0 at index 2;
 * `filter 1, 0.5 transmit 5, 0.3 transmit 0, 0.1 transmit all 0.2`:
 * every t 0.2, f 0.5 at index 1 only (not at 4, the same green);
 * `transmit all 0.2 transmit 5, 0.3 filter all 0.1 filter 1, 0.6`: index
 * 0 f 0.1 t 0.2, index 1 f 0.6 t 0.2, index 5 f 0.1 t 0.3. */
static void test_palette(void **state)
{
	(void)state;
	struct image *img = load("pal.png", 1.0);
	assert_int_equal(img->palette_size, 6);
	static const int want[8] = {0, 1, 2, 3, 4, 5, 0, 1};
	for (int i = 0; i < 8; i++)
		assert_int_equal(img->index[i], want[i]);
	struct image_mapping m = mapping(img);
	int index = -1;
	struct rgbft c;
	assert_true(image_map_eval(&m, v3(0.125, 0.25, 0), &c, &index));
	assert_int_equal(index, 4);
	assert_at(m, 0.125, 0.75, 0, 255, 0, 0, 0, 0.498, 1e-3);
	assert_at(m, 0.625, 0.75, 0, 0, 0, 255, 0, 1, 1e-3);
	assert_at(m, 0.375, 0.25, 0, 40, 80, 120, 0, 0, 1e-3);

	/* transmit all after the per-index ones overrides them (the parser
	 * drops them); per-index ones after `all` win. */
	__typeof__(m.entry[0]) e[3] = {{.index = 1, .filter = 0.6, .has_filter = true},
	                           {.index = 5, .transmit = 0.3, .has_transmit = true}};
	m.entry = e;
	m.nentry = 2;
	m.has_transmit_all = m.has_filter_all = true;
	m.transmit_all = 0.2;
	m.filter_all = 0.1;
	assert_at(m, 0.125, 0.75, 0, 255, 0, 0, 0.1, 0.2, 1e-3);
	assert_at(m, 0.375, 0.75, 0, 0, 255, 0, 0.6, 0.2, 1e-3);
	assert_at(m, 0.375, 0.25, 0, 40, 80, 120, 0.1, 0.3, 1e-3);
	assert_at(m, 0.125, 0.25, 0, 0, 255, 0, 0.1, 0.2, 1e-3);
	image_unref(img);

	img = load("pal.gif", 1.0);
	assert_int_equal(img->palette_size, 256);
	for (int i = 0; i < 8; i++)
		assert_int_equal(img->index[i], want[i]);
	m = mapping(img);
	assert_at(m, 0.625, 0.75, 0, 0, 0, 255, 0, 1, 1e-3);
	assert_at(m, 0.375, 0.25, 0, 40, 80, 120, 0, 0, 1e-3);
	image_unref(img);

	/* material_map without a palette: the stored red value (POV-Ray chose
	 * textures 10, 70, 130, 190 mod 7 = 3 0 4 1 across rgb.png). */
	img = load("rgb.png", 0);
	m = mapping(img);
	static const int chosen[4] = {3, 0, 4, 1};
	for (int col = 0; col < 4; col++) {
		assert_true(image_map_eval(&m, v3((col + 0.5) / 4, 0.3, 0), &c, &index));
		assert_int_equal(index % 7, chosen[col]);
	}
	image_unref(img);
}

/* image_pattern values, POV-Ray `function { pattern { image_pattern {..} } }`:
 * rgb.png (0.125, 0.75) 0.147255, (0.625, 0.25) 0.482235 (stored values,
 * no decoding); gamma srgb 0.070866 0.198337; rgba.png 0.297 0.506667,
 * use_alpha 0 0.8; pal.png 0.297 0.589 0.114, use_alpha 0.498039 0 1;
 * rgb.png use_alpha (no alpha): the red value 0.039216, 0.274510;
 * interpolate 2 at (0.25, 0.75) 0.173255; once outside 0; float.exr
 * 1 (clamped) and 0.450125. */
static void test_pattern_value(void **state)
{
	(void)state;
	struct image *img = load("rgb.png", 0);
	struct image_mapping m = mapping(img);
	assert_near(image_map_value(&m, v3(0.125, 0.75, 0)), 0.147255, 1e-5);
	assert_near(image_map_value(&m, v3(0.625, 0.25, 0)), 0.482235, 1e-5);
	m.interpolate = 2;
	assert_near(image_map_value(&m, v3(0.25, 0.75, 0)), 0.173255, 1e-5);
	m.interpolate = 0;
	m.use_alpha = true;
	assert_near(image_map_value(&m, v3(0.125, 0.75, 0)), 0.039216, 1e-5);
	assert_near(image_map_value(&m, v3(0.375, 0.25, 0)), 0.274510, 1e-5);
	m.use_alpha = false;
	m.once = true;
	assert_near(image_map_value(&m, v3(1.5, 0.5, 0)), 0, 0);
	image_unref(img);
	img = load("rgb.png", IMAGE_GAMMA_SRGB);
	m = mapping(img);
	m.gamma = IMAGE_GAMMA_SRGB;
	assert_near(image_map_value(&m, v3(0.125, 0.75, 0)), 0.070866, 1e-5);
	assert_near(image_map_value(&m, v3(0.625, 0.25, 0)), 0.198337, 1e-5);
	image_unref(img);
	img = load("rgba.png", 0);
	m = mapping(img);
	assert_near(image_map_value(&m, v3(0.25, 0.5, 0)), 0.297, 1e-5);
	assert_near(image_map_value(&m, v3(0.75, 0.5, 0)), 0.506667, 1e-5);
	m.use_alpha = true;
	assert_near(image_map_value(&m, v3(0.25, 0.5, 0)), 0, 1e-5);
	assert_near(image_map_value(&m, v3(0.75, 0.5, 0)), 0.8, 1e-5);
	image_unref(img);
	img = load("pal.png", 0);
	m = mapping(img);
	assert_near(image_map_value(&m, v3(0.125, 0.75, 0)), 0.297, 1e-5);
	assert_near(image_map_value(&m, v3(0.375, 0.75, 0)), 0.589, 1e-5);
	assert_near(image_map_value(&m, v3(0.625, 0.75, 0)), 0.114, 1e-5);
	m.use_alpha = true;
	assert_near(image_map_value(&m, v3(0.125, 0.75, 0)), 0.498039, 1e-5);
	assert_near(image_map_value(&m, v3(0.625, 0.75, 0)), 1, 1e-5);
	m.use_alpha = false;
	m.use_index = true;
	assert_near(image_map_value(&m, v3(0.375, 0.25, 0)), 5 / 255.0, 1e-9);
	image_unref(img);
	img = load("float.exr", 0);
	m = mapping(img);
	assert_near(image_map_value(&m, v3(0.25, 0.5, 0)), 1, 0);
	assert_near(image_map_value(&m, v3(0.75, 0.5, 0)), 0.450125, 1e-5);
	image_unref(img);
}

/* The cache: the same file and decoding is read once. */
static void test_cache(void **state)
{
	(void)state;
	struct image *a = load("rgb.png", 0), *b = load("rgb.png", 0), *c = load("rgb.png", 1.0);
	assert_ptr_equal(a, b);
	assert_ptr_not_equal(a, c);
	assert_int_equal(a->refs, 2);
	image_unref(a);
	image_unref(b);
	image_unref(c);
	char err[256];
	assert_null(image_load("/nonexistent/x.png", 0, err, sizeof err));
	assert_true(err[0] != 0);
}

/* ---- parsing ---- */

/* Parse `text` (the inside of an image block, then '}') as if it were the
 * file tests/data/images/t.pov. Returns 0 and fills m on success (the
 * parse stopped at the '}'), 1 on an error (its message in msg). */
static int parse_block(const char *text, struct image_mapping *m, char *msg, size_t msgsize)
{
	char scene[4200];
	snprintf(scene, sizeof scene, "%s/t.pov", dir);
	struct srcmgr *sm = src_new();
	uint32_t file = src_add(sm, scene, strdup(text), strlen(text));
	memset(msg, 0, msgsize);
	FILE *out = fmemopen(msg, msgsize - 1, "w");
	struct diag d;
	diag_init(&d, sm, out);
	struct parse_opts o = {.input = scene};
	struct parser *p = calloc(1, sizeof *p);
	jmp_buf jb;
	p->sm = sm;
	p->d = &d;
	p->o = &o;
	p->names = sm->names;
	p->boundary = &jb;
	p->globals = sym_new();
	p->version = 3.7;
	parse_limits_default(&p->lim);
	p->capframes = 4;
	p->frames = calloc((size_t)p->capframes, sizeof *p->frames);
	int rc;
	if (setjmp(jb) == 0) {
		parse_push_file(p, file, (struct srcpos){0, 0, 0});
		parse_image_mapping(p, m);
		rc = parse_is(p, TOK_RBRACE) ? 0 : 2;
	} else {
		rc = 1;
	}
	for (int i = p->nowned - 1; i >= 0; i--)
		if (p->owned[i].ptr)
			p->owned[i].free(p->owned[i].ptr);
	for (int i = p->nframes - 1; i >= 0; i--)
		sym_free(p->frames[i].locals);
	sym_free(p->globals);
	free(p->frames);
	free(p);
	fclose(out);
	src_free(sm);
	return rc;
}

static void clear(struct image_mapping *m)
{
	image_unref(m->img);
	free(m->entry);
}

/* image_map's colours in the working gamma: POV-Ray 3.7.0 with
 * global_settings { assumed_gamma 2.2 } printed, for
 * function { pigment { image_map { png "rgb.png" } } }, at (0.1, 0.1, 0)
 * 0.071704149, 0.467609644, 0.779187679 and at (0.7, 0.4, 0) 0.505797505,
 * 0.467609644, 0.467609644; with gamma 1.5 at (0.7, 0.4, 0) 0.631687343,
 * 0.598137081, 0.598137081 (the decoded values to the power 1/2.2). */
static void test_working_gamma(void **state)
{
	(void)state;
	char path[4200], err[512];
	snprintf(path, sizeof path, "%s/rgb.png", dir);
	struct image_mapping m = mapping(load("rgb.png", 0));
	assert_true(image_mapping_to_working(&m, 2.2, err, sizeof err));
	assert_near(m.img->working, 2.2, 0);
	struct rgbft c;
	image_map_eval(&m, v3(0.1, 0.1, 0), &c, NULL);
	assert_near(c.r, 0.071704149, 1e-6);
	assert_near(c.g, 0.467609644, 1e-6);
	assert_near(c.b, 0.779187679, 1e-6);
	image_map_eval(&m, v3(0.7, 0.4, 0), &c, NULL);
	assert_near(c.r, 0.505797505, 1e-6);
	assert_near(c.g, 0.467609644, 1e-6);
	image_unref(m.img);
	struct image_mapping g = mapping(image_load_working(path, 1.5, -1, 2.2, err, sizeof err));
	assert_non_null(g.img);
	image_map_eval(&g, v3(0.7, 0.4, 0), &c, NULL);
	assert_near(c.r, 0.631687343, 1e-6);
	assert_near(c.g, 0.598137081, 1e-6);
	/* the linear image is another cache entry, untouched */
	struct image *lin = load("rgb.png", 1.5);
	assert_ptr_not_equal(lin, g.img);
	image_unref(lin);
	image_unref(g.img);
}

static void test_parse(void **state)
{
	(void)state;
	char msg[2048];
	struct image_mapping m;
	assert_int_equal(parse_block("png \"rgb.png\" gamma 2.2 premultiplied off map_type 2 once interpolate 2 }", &m,
	                             msg, sizeof msg), 0);
	assert_non_null(m.img);
	assert_near(m.gamma, 2.2, 0);
	assert_int_equal(m.premultiplied, 0);
	assert_int_equal(m.map_type, 2);
	assert_int_equal(m.interpolate, 2);
	assert_true(m.once);
	clear(&m);
	/* No type: the extension; a type and no extension: the type's (POV-Ray
	 * reads `png "rgb"` as rgb.png); map_type 1.7 is 1, as in POV-Ray. */
	assert_int_equal(parse_block("\"rgb.png\" gamma srgb }", &m, msg, sizeof msg), 0);
	assert_true(m.gamma == IMAGE_GAMMA_SRGB);
	clear(&m);
	assert_int_equal(parse_block("png \"rgb\" map_type 1.7 }", &m, msg, sizeof msg), 0);
	assert_int_equal(m.map_type, 1);
	clear(&m);
	/* Palette amounts: `all` drops the per-index ones before it. */
	assert_int_equal(parse_block("gif \"pal\" filter 1, 0.5 transmit 5, 0.3 transmit all 0.2 transmit 2, 0.7 "
	                             "use_index use_alpha }", &m, msg, sizeof msg), 0);
	assert_int_equal(m.nentry, 3);
	assert_true(m.entry[0].has_filter && m.entry[0].index == 1);
	assert_false(m.entry[1].has_transmit);
	assert_true(m.entry[2].has_transmit && m.entry[2].index == 2);
	assert_true(m.has_transmit_all && m.use_index && m.use_alpha);
	clear(&m);
	/* It stops at what it does not know. */
	assert_int_equal(parse_block("png \"rgb.png\" once bump_size 2 }", &m, msg, sizeof msg), 2);
	clear(&m);

	/* Errors, each at the offending token. */
	static const struct { const char *text, *want; } bad[] = {
		{"png \"missing.png\" }", "t.pov:1:5: error: cannot find image file \"missing.png\""},
		{"png \"make.py\" }", "t.pov:1:5: error: cannot read image file \"make.py\""},
		{"png \"rgb.png\" map_type 3 }", "t.pov:1:24: error: map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), not 3"},
		{"png \"rgb.png\" interpolate 1 }", "t.pov:1:27: error: interpolate must be 2 (bilinear), 3 (bicubic) or 4 (normalized distance), not 1"},
		{"png \"rgb.png\" filter 1, 0.5 }", "t.pov:1:15: error: 'filter 1, ...' needs an image with a palette"},
		{"png \"pal.png\" transmit 6, 0.5 }", "t.pov:1:24: error: palette index 6 is out of range"},
		{"png \"rgb.png\" gamma 0 }", "t.pov:1:21: error: an image's gamma must be greater than 0, or srgb"},
		{"png once }", "t.pov:1:5: error: expected an image file name"},
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		memset(&m, 0, sizeof m);
		assert_int_equal(parse_block(bad[i].text, &m, msg, sizeof msg), 1);
		assert_null(m.img);
		if (!strstr(msg, bad[i].want))
			fail_msg("for '%s' got:\n%s\nwanted: %s", bad[i].text, msg, bad[i].want);
	}
}

/* image_map { function W, H { ... } }: POV-Ray 3.7.0 printed, through
 * function { pigment { image_map { function ... } } }, 0.29999238 for the
 * constant 0.3, 0.49997711 for 1.5, 0.75002670 for -0.25, 0.70000762 for
 * 0.7000076 (16-bit storage by truncation in single precision, wrapping),
 * and for { x } (4 x 4) at x = 0.125 .. 0.875 the columns 0, 1/3, 2/3, 1;
 * for { y } at y = 0.125 .. 0.875 the rows 1, 2/3, 1/3, 0 (the function's
 * y = 0 is the image's top row). */
static void test_function_image(void **state)
{
	(void)state;
	char msg[2048];
	static const struct { const char *text; double v; } consts[] = {
		{"function 2, 2 { 0.3 } }", 0.29999238}, {"function 2, 2 { 1.5 } }", 0.49997711},
		{"function 2, 2 { -0.25 } }", 0.75002670}, {"function 2, 2 { 0.7000076 } }", 0.70000762},
		{"function 2, 2 { pattern { function { 0.3 } } } }", 0.29999238},
	};
	struct image_mapping m;
	struct rgbft c;
	for (size_t i = 0; i < sizeof consts / sizeof consts[0]; i++) {
		assert_int_equal(parse_block(consts[i].text, &m, msg, sizeof msg), 0);
		image_map_eval(&m, v3(0.1, 0.1, 0), &c, NULL);
		assert_near(c.r, consts[i].v, 1e-7);
		assert_near(c.t, 0, 0);
		clear(&m);
	}
	assert_int_equal(parse_block("function 4, 4 { x } }", &m, msg, sizeof msg), 0);
	assert_int_equal(m.img->width, 4);
	for (int i = 0; i < 4; i++) {
		image_map_eval(&m, v3((i + 0.5) / 4, 0.5, 0), &c, NULL);
		assert_near(c.r, i / 3.0, 1e-7);
	}
	clear(&m);
	assert_int_equal(parse_block("function 4, 4 { y } interpolate 2 }", &m, msg, sizeof msg), 0);
	assert_int_equal(m.interpolate, 2);
	m.interpolate = 0;
	for (int i = 0; i < 4; i++) {
		image_map_eval(&m, v3(0.5, (i + 0.5) / 4, 0), &c, NULL);
		assert_near(c.r, 1 - i / 3.0, 1e-7);
	}
	clear(&m);
	assert_int_equal(parse_block("function 0, 2 { x } }", &m, msg, sizeof msg), 1);
	if (!strstr(msg, "t.pov:1:10: error: a function image's width must be at least 1, not 0"))
		fail_msg("got:\n%s", msg);
}

int main(void)
{
	setup_paths();
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_planar_addressing), cmocka_unit_test(test_gamma),
		cmocka_unit_test(test_interpolation),     cmocka_unit_test(test_map_types),
		cmocka_unit_test(test_alpha),             cmocka_unit_test(test_palette),
		cmocka_unit_test(test_pattern_value),     cmocka_unit_test(test_cache),
		cmocka_unit_test(test_parse),               cmocka_unit_test(test_working_gamma),
		cmocka_unit_test(test_function_image),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

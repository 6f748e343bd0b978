/* test_shade.c: unit tests for the material formulas of render/shade.c.
 * Every expected value was measured in POV-Ray 3.7: a plane facing the
 * camera, rendered 1x1 to a 16-bit linear PNG (+FN16 File_Gamma=1.0),
 * lit and seen at the angles given, the term isolated by setting the other
 * finish terms to 0. The figures are quoted beside each check. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "render/shade.h"

#include <math.h>

#include "testutil.h"

static double cosd(double a) { return cos(a * M_PI / 180); }

/* phong 1 phong_size 1 metallic, pigment <1, 0.5, 0.2>, light in the mirror
 * direction at 30, 60, 80 degrees: green 0.5059587, 0.5296407, 0.6305638
 * (so the curve is 0.0119, 0.0593, 0.2611). */
static void test_metallic(void **state)
{
	(void)state;
	rgb pig = rgb_make(1, 0.5, 0.2);
	assert_near(shade_metallic(pig, 1, cosd(30)).g, 0.5059587, 2e-5);
	assert_near(shade_metallic(pig, 1, cosd(60)).g, 0.5296407, 2e-5);
	assert_near(shade_metallic(pig, 1, cosd(80)).g, 0.6305638, 2e-5);
	assert_near(shade_metallic(pig, 1, cosd(80)).b, 0.408896, 2e-5);
	/* metallic 0.5 at 60 degrees: 0.7648127 */
	assert_near(shade_metallic(pig, 0.5, cosd(60)).g, 0.7648127, 2e-5);
	/* head-on, metallic 1 is the pigment */
	assert_near(shade_metallic(pig, 1, 1).g, 0.5000076, 2e-4);
}

/* reflection { 0, 1 fresnel } with interior { ior 1.5 } at 0, 30, 60, 80
 * degrees: 0.0399939, 0.0415198, 0.0891890, 0.3877012. */
static void test_fresnel(void **state)
{
	(void)state;
	assert_near(shade_fresnel(1, 1.5), 0.0399939, 3e-5);
	assert_near(shade_fresnel(cosd(30), 1.5), 0.0415198, 3e-5);
	assert_near(shade_fresnel(cosd(60), 1.5), 0.0891890, 3e-5);
	assert_near(shade_fresnel(cosd(80), 1.5), 0.3877012, 3e-5);
	/* from inside glass beyond the critical angle (41.8 degrees) */
	assert_near(shade_fresnel(cosd(60), 1 / 1.5), 1.0, 0);
}

/* diffuse albedo 0.6 brilliance 3 lit at 30 degrees: 0.7794156 against
 * 0.3897154 without albedo; phong albedo 0.1 phong_size 10 head-on:
 * 0.5499962; specular albedo 0.1 roughness 0.1: 0.1523766, roughness 1:
 * 0.0580148. */
static void test_albedo(void **state)
{
	(void)state;
	assert_near(shade_albedo_diffuse(3), 0.7794156 / 0.3897154, 1e-4);
	assert_near(shade_albedo_diffuse(1), 1, 0);
	assert_near(0.1 * shade_albedo_phong(10), 0.5499962, 2e-5);
	assert_near(0.1 * shade_albedo_specular(10), 0.1523766, 2e-5);
	assert_near(0.1 * shade_albedo_specular(1), 0.0580148, 2e-5);
}

/* A box of rgbf 1 and ior 1, seen through at depth d against white:
 * fade_distance 1. */
static void test_fade(void **state)
{
	(void)state;
	struct interior in = {.fade_distance = 1, .fade_power = 1};
	assert_near(shade_fade(&in, 0.5).r, 0.6666667, 2e-5);  /* power 1 */
	assert_near(shade_fade(&in, 2).r, 0.3333333, 2e-5);
	in.fade_power = 2;
	in.fade_color = rgb_make(0.5, 0.2, 0.9);
	rgb c = shade_fade(&in, 0.5);                          /* 0.9000076 0.8399939 0.9799954 */
	assert_near(c.r, 0.9000076, 2e-5);
	assert_near(c.g, 0.8399939, 2e-5);
	assert_near(c.b, 0.9799954, 2e-5);
	in.fade_power = 1000;
	c = shade_fade(&in, 2);                                /* 0.36787975 0.20189212 0.8187381 */
	assert_near(c.r, 0.3678798, 2e-5);
	assert_near(c.g, 0.2018921, 2e-5);
	assert_near(c.b, 0.8187381, 2e-5);
}

/* A disc of rgbf 0.8 with caustics between a light and a lit plane: the
 * plane's light, relative to no caustics, at 0 and 10 degrees: caustics 1
 * 2.00084, 1.50301; caustics 0.5 at 10: 1.70901; caustics 2 at 20: 1.00328. */
static void test_caustics(void **state)
{
	(void)state;
	assert_near(shade_caustics(1, 1), 2.0, 2e-3);
	assert_near(shade_caustics(cosd(10), 1), 1.50301, 3e-3);
	assert_near(shade_caustics(cosd(10), 0.5), 1.70901, 3e-3);
	assert_near(shade_caustics(cosd(20), 2), 1.00328, 3e-3);
}

/* irid { 0.25 thickness 0.3 }, diffuse 1, pigment 0.5, light head-on:
 * 0.57794 0.57101 0.49999, i.e. 0.5 (1 + irid); with the light at 30
 * degrees: 0.46629 0.52898 0.48737. */
static void test_irid(void **state)
{
	(void)state;
	rgb wl = rgb_make(0.70, 0.52, 0.48);
	rgb ir = shade_irid(0.25, 0.3, 1, wl);
	assert_near(0.5 * (1 + ir.r), 0.57794, 1e-4);
	assert_near(0.5 * (1 + ir.g), 0.57101, 1e-4);
	assert_near(0.5 * (1 + ir.b), 0.49999, 1e-4);
	double c = cosd(30);
	ir = shade_irid(0.25, 0.3, (c + 1) / 2, wl);
	assert_near(0.5 * c * (1 + ir.r), 0.46629, 1e-4);
	assert_near(0.5 * c * (1 + ir.g), 0.52898, 1e-4);
	assert_near(0.5 * c * (1 + ir.b), 0.48737, 1e-4);
}

static void test_refract(void **state)
{
	(void)state;
	/* Snell: 30 degrees in air to glass 1.5: sin = 0.5 / 1.5. */
	vec3 d = v3(sin(M_PI / 6), -cos(M_PI / 6), 0), out;
	assert_true(shade_refract(d, v3(0, 1, 0), 1 / 1.5, &out));
	assert_near(out.x, 0.5 / 1.5, 1e-12);
	assert_near(v3_len(out), 1, 1e-12);
	/* 60 degrees from glass to air: total internal reflection */
	d = v3(sin(M_PI / 3), -cos(M_PI / 3), 0);
	assert_false(shade_refract(d, v3(0, 1, 0), 1.5, &out));
}

static void test_dispersion(void **state)
{
	(void)state;
	/* POV-Ray 3.7's bands, read from 16-bit renders of a white background
	 * seen through a prism (one band crossing an edge between black and
	 * white at a time): 2, 3 and 5 samples, red first. */
	static const struct {
		int n;
		double c[5][3];
	} bands[] = {
	    {2, {{0.95430, 0.72760, 0.01221}, {0.03951, 0.27240, 0.98399}}},
	    {3, {{0.79501, 0.26363, 0}, {0.15929, 0.73487, 0.30179}, {0.03951, 0.00150, 0.69441}}},
	    {5,
	     {{0.42161, 0.01830, 0},
	      {0.49509, 0.42870, 0},
	      {0.03760, 0.49180, 0.15061},
	      {0, 0.06120, 0.50239},
	      {0.03951, 0, 0.34321}}},
	};
	for (size_t k = 0; k < sizeof bands / sizeof bands[0]; k++) {
		for (int i = 0; i < bands[k].n; i++) {
			rgb c = shade_dispersion_color(i, bands[k].n);
			assert_near(c.r, bands[k].c[i][0], 4e-5);
			assert_near(c.g, bands[k].c[i][1], 4e-5);
			assert_near(c.b, bands[k].c[i][2], 4e-5);
		}
	}
	/* The whole spectrum, whatever the number of bands: (0.9938, 1, 0.9962). */
	for (int n = 2; n <= 151; n++) {
		rgb sum = rgb_make(0, 0, 0);
		for (int i = 0; i < n; i++)
			sum = rgb_add(sum, shade_dispersion_color(i, n));
		assert_near(sum.r, 0.99380, 2e-5);
		assert_near(sum.g, 1, 2e-5);
		assert_near(sum.b, 0.99620, 2e-5);
	}
	/* Measured band iors: ior * dispersion^hue with hue -1/4, 1/4 for 2
	 * samples and -1/3, 0, 1/3 for 3 (within 0.001 of the exponent). */
	assert_near(shade_dispersion_hue(0, 2), -0.25, 1e-12);
	assert_near(shade_dispersion_hue(1, 2), 0.25, 1e-12);
	assert_near(shade_dispersion_hue(0, 3), -1.0 / 3, 1e-12);
	assert_near(shade_dispersion_hue(1, 3), 0, 1e-12);
	assert_near(shade_dispersion_hue(6, 7), 3.0 / 7, 1e-12);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_metallic),
		cmocka_unit_test(test_fresnel),
		cmocka_unit_test(test_albedo),
		cmocka_unit_test(test_fade),
		cmocka_unit_test(test_caustics),
		cmocka_unit_test(test_irid),
		cmocka_unit_test(test_refract),
		cmocka_unit_test(test_dispersion),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

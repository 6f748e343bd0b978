/* test_camera.c: the projections of scene/camera.c and the camera
 * statement of lang/camera_parse.c against POV-Ray 3.7.
 *
 * How the expected values were obtained: each camera below was rendered
 * by POV-Ray 3.7 (no antialiasing) looking at a hollow sphere of radius
 * 1000 centred on its location, pigment 0.5 + 0.5 * (x - location.x) /
 * 1000 (then y, then z), ambient 1, to 16-bit PNGs with File_Gamma=1.0:
 * each pixel then holds one component of the unit vector from the centre
 * to where the ray through the pixel's centre leaves the sphere (its
 * direction, for rays from the centre), to about 3e-5 (black, -1 -1 -1
 * here, where POV-Ray shoots no ray). The origin checks rendered a plane z = PZ with pigment
 * 0.5 + 0.5 * x / 20 (then y): the point where the pixel's ray meets that
 * plane, to 40/65535 = 6e-4. The tables list (camera items, image width
 * and height, pixel column and row, whether there is a ray, and the
 * measured values). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "lang/diag.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "testutil.h"

/* Parse `camera { items }` and return the scene's camera (camera_clear
 * it if it may hold references: a mesh camera). */
static struct camera parse_cam(const char *items)
{
	char path[64];
	snprintf(path, sizeof path, "/tmp/lucent-test-camera-%d.pov", (int)getpid());
	FILE *f = fopen(path, "w");
	assert_non_null(f);
	fprintf(f, "#version 3.7;\ncamera { %s }\n", items);
	fclose(f);
	struct srcmgr *sm = src_new();
	struct diag d;
	diag_init(&d, sm, stderr);
	struct scene *s = scene_new();
	struct parse_opts o = {.input = path, .image_width = 8, .image_height = 8, .debug_out = stderr};
	int rc = parse_scene(sm, &d, &o, s);
	if (rc != 0)
		fail_msg("camera { %s } did not parse", items);
	struct camera c;
	camera_copy(&c, &s->camera); /* a mesh camera's faces outlive the scene */
	scene_free(s);
	src_free(sm);
	remove(path);
	return c;
}

struct dir_case {
	const char *cam;
	vec3 centre; /* of the sphere of radius 1000 */
	int w, h, px, py;
	bool ray;
	double d[3];
};

static const struct dir_case dir_cases[] = {
	{"location 0 look_at z", {0, 0, 0}, 8, 6, 0, 0, true, {-0.47317, 0.33883, 0.81320}},
	{"location 0 look_at z", {0, 0, 0}, 8, 6, 4, 2, true, {0.08257, 0.08275, 0.99313}},
	{"location 0 look_at z", {0, 0, 0}, 8, 6, 7, 5, true, {0.47317, -0.33883, 0.81320}},
	{"location 0 look_at z", {0, 0, 0}, 8, 6, 3, 2, true, {-0.08257, 0.08275, 0.99313}},
	{"location 0 look_at z", {0, 0, 0}, 8, 6, 1, 3, true, {-0.38265, -0.07674, 0.92068}},
	{"fisheye location 0 look_at z angle 180", {0, 0, 0}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 look_at z angle 180", {0, 0, 0}, 16, 12, 8, 5, true, {0.12984, 0.13014, 0.98297}},
	{"fisheye location 0 look_at z angle 180", {0, 0, 0}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 look_at z angle 180", {0, 0, 0}, 16, 12, 3, 2, true, {-0.78604, 0.61291, 0.08055}},
	{"fisheye location 0 look_at z angle 180", {0, 0, 0}, 16, 12, 1, 6, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 angle 120 right 2*x up y direction 3*z", {0, 0, 0}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 angle 120 right 2*x up y direction 3*z", {0, 0, 0}, 16, 12, 8, 5, true, {0.13036, 0.08690, 0.98764}},
	{"fisheye location 0 angle 120 right 2*x up y direction 3*z", {0, 0, 0}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 angle 120 right 2*x up y direction 3*z", {0, 0, 0}, 16, 12, 3, 2, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0 angle 120 right 2*x up y direction 3*z", {0, 0, 0}, 16, 12, 1, 6, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0", {0, 0, 0}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.06520, 0.06535, 0.99573}},
	{"fisheye location 0", {0, 0, 0}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.53469, 0.41692, 0.73504}},
	{"fisheye location 0", {0, 0, 0}, 16, 12, 1, 6, false, {-1.00000, -1.00000, -1.00000}},
	{"ultra_wide_angle location 0 angle 120 right 2*x up y", {0, 0, 0}, 16, 12, 0, 0, true, {-0.77624, 0.43108, 0.46004}},
	{"ultra_wide_angle location 0 angle 120 right 2*x up y", {0, 0, 0}, 16, 12, 8, 5, true, {0.06542, 0.04363, 0.99692}},
	{"ultra_wide_angle location 0 angle 120 right 2*x up y", {0, 0, 0}, 16, 12, 15, 11, true, {0.77624, -0.43108, 0.46004}},
	{"ultra_wide_angle location 0 angle 120 right 2*x up y", {0, 0, 0}, 16, 12, 3, 2, true, {-0.54797, 0.29659, 0.78216}},
	{"ultra_wide_angle location 0 angle 120 right 2*x up y", {0, 0, 0}, 16, 12, 1, 6, true, {-0.75143, -0.04360, 0.65835}},
	{"ultra_wide_angle location <1,2,3> right 1*x up 2*y direction 3*z angle 200", {1, 2, 3}, 16, 12, 0, 0, true, {-0.99619, -0.05806, 0.06517}},
	{"ultra_wide_angle location <1,2,3> right 1*x up 2*y direction 3*z angle 200", {1, 2, 3}, 16, 12, 8, 5, true, {0.10881, 0.28667, 0.95184}},
	{"ultra_wide_angle location <1,2,3> right 1*x up 2*y direction 3*z angle 200", {1, 2, 3}, 16, 12, 15, 11, true, {0.99619, 0.05806, 0.06517}},
	{"ultra_wide_angle location <1,2,3> right 1*x up 2*y direction 3*z angle 200", {1, 2, 3}, 16, 12, 3, 2, true, {-0.66741, 0.71731, -0.20015}},
	{"ultra_wide_angle location <1,2,3> right 1*x up 2*y direction 3*z angle 200", {1, 2, 3}, 16, 12, 1, 6, true, {-0.95090, -0.27593, 0.14022}},
	{"ultra_wide_angle location <1,2,3> look_at <3,1,8> sky <0.3,1,0>", {1, 2, 3}, 16, 12, 0, 0, true, {-0.18441, 0.51864, 0.83487}},
	{"ultra_wide_angle location <1,2,3> look_at <3,1,8> sky <0.3,1,0>", {1, 2, 3}, 16, 12, 8, 5, true, {0.42269, -0.14842, 0.89404}},
	{"ultra_wide_angle location <1,2,3> look_at <3,1,8> sky <0.3,1,0>", {1, 2, 3}, 16, 12, 15, 11, true, {0.62268, -0.73776, 0.26076}},
	{"ultra_wide_angle location <1,2,3> look_at <3,1,8> sky <0.3,1,0>", {1, 2, 3}, 16, 12, 3, 2, true, {0.04143, 0.27416, 0.96078}},
	{"ultra_wide_angle location <1,2,3> look_at <3,1,8> sky <0.3,1,0>", {1, 2, 3}, 16, 12, 1, 6, true, {-0.24453, -0.03642, 0.96896}},
	{"omnimax location 0", {0, 0, 0}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.08846, 0.39028, 0.91644}},
	{"omnimax location 0", {0, 0, 0}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.63561, 0.73645, 0.23159}},
	{"omnimax location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.93835, 0.17379, 0.29879}},
	{"omnimax location 0 right 2*x up y", {0, 0, 0}, 32, 32, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 2*x up y", {0, 0, 0}, 32, 32, 16, 15, true, {0.06709, 0.33779, 0.93884}},
	{"omnimax location 0 right 2*x up y", {0, 0, 0}, 32, 32, 31, 31, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 2*x up y", {0, 0, 0}, 32, 32, 3, 2, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 2*x up y", {0, 0, 0}, 32, 32, 1, 16, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 0.8*x up y", {0, 0, 0}, 32, 32, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 0.8*x up y", {0, 0, 0}, 32, 32, 16, 15, true, {0.04405, 0.05507, 0.99750}},
	{"omnimax location 0 right 0.8*x up y", {0, 0, 0}, 32, 32, 31, 31, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 0.8*x up y", {0, 0, 0}, 32, 32, 3, 2, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right 0.8*x up y", {0, 0, 0}, 32, 32, 1, 16, true, {-0.97848, -0.04216, 0.20201}},
	{"omnimax location 0 right x up y", {0, 0, 0}, 64, 64, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right x up y", {0, 0, 0}, 64, 64, 32, 31, true, {0.02205, 0.02205, 0.99951}},
	{"omnimax location 0 right x up y", {0, 0, 0}, 64, 64, 63, 63, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right x up y", {0, 0, 0}, 64, 64, 3, 2, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location 0 right x up y", {0, 0, 0}, 64, 64, 1, 32, true, {-0.99435, -0.01631, 0.10500}},
	{"omnimax location <1,2,3> look_at <3,1,8> right -1.33*x", {1, 2, 3}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location <1,2,3> look_at <3,1,8> right -1.33*x", {1, 2, 3}, 16, 12, 8, 5, true, {0.27898, 0.21642, 0.93561}},
	{"omnimax location <1,2,3> look_at <3,1,8> right -1.33*x", {1, 2, 3}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"omnimax location <1,2,3> look_at <3,1,8> right -1.33*x", {1, 2, 3}, 16, 12, 3, 2, true, {0.72467, 0.68179, 0.10018}},
	{"omnimax location <1,2,3> look_at <3,1,8> right -1.33*x", {1, 2, 3}, 16, 12, 1, 6, true, {0.99213, 0.11632, -0.04628}},
	{"panoramic location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.17165, 0.98508, 0.01271}},
	{"panoramic location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.12877, 0.13005, 0.98309}},
	{"panoramic location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.17165, -0.98508, 0.01271}},
	{"panoramic location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.57855, 0.73336, 0.35698}},
	{"panoramic location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.97003, -0.10033, 0.22124}},
	{"panoramic location 0 direction 2*z", {0, 0, 0}, 16, 12, 0, 0, true, {-0.17162, 0.98483, 0.02541}},
	{"panoramic location 0 direction 2*z", {0, 0, 0}, 16, 12, 8, 5, true, {0.06520, 0.06587, 0.99570}},
	{"panoramic location 0 direction 2*z", {0, 0, 0}, 16, 12, 15, 11, true, {0.17162, -0.98483, 0.02541}},
	{"panoramic location 0 direction 2*z", {0, 0, 0}, 16, 12, 3, 2, true, {-0.49209, 0.62377, 0.60726}},
	{"panoramic location 0 direction 2*z", {0, 0, 0}, 16, 12, 1, 6, true, {-0.90582, -0.09371, 0.41320}},
	{"spherical location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.02547, 0.99145, -0.12801}},
	{"spherical location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.19341, 0.13054, 0.97238}},
	{"spherical location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.02547, -0.99145, -0.12801}},
	{"spherical location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.59707, 0.79336, -0.11876}},
	{"spherical location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.55080, -0.13054, -0.82437}},
	{"spherical location <1,2,3> look_at <3,1,8> angle 300 100", {1, 2, 3}, 16, 12, 0, 0, true, {-0.55843, 0.80359, -0.20592}},
	{"spherical location <1,2,3> look_at <3,1,8> angle 300 100", {1, 2, 3}, 16, 12, 8, 5, true, {0.51510, -0.10823, 0.85028}},
	{"spherical location <1,2,3> look_at <3,1,8> angle 300 100", {1, 2, 3}, 16, 12, 15, 11, true, {0.16509, -0.60693, -0.77743}},
	{"spherical location <1,2,3> look_at <3,1,8> angle 300 100", {1, 2, 3}, 16, 12, 3, 2, true, {-0.74255, 0.46352, 0.48348}},
	{"spherical location <1,2,3> look_at <3,1,8> angle 300 100", {1, 2, 3}, 16, 12, 1, 6, true, {-0.98361, 0.02473, -0.17855}},
	{"cylinder 1 location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.61050, 0.41665, 0.67358}},
	{"cylinder 1 location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.04903, 0.04164, 0.99792}},
	{"cylinder 1 location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.61050, -0.41665, 0.67358}},
	{"cylinder 1 location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.41045, 0.27999, 0.86783}},
	{"cylinder 1 location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.59518, -0.04164, 0.80252}},
	{"cylinder 1 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8>", {1, 2, 3}, 16, 12, 0, 0, true, {-0.21437, 0.56466, 0.79699}},
	{"cylinder 1 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8>", {1, 2, 3}, 16, 12, 8, 5, true, {0.41448, -0.10008, 0.90454}},
	{"cylinder 1 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8>", {1, 2, 3}, 16, 12, 15, 11, true, {0.61324, -0.76410, 0.20021}},
	{"cylinder 1 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8>", {1, 2, 3}, 16, 12, 3, 2, true, {-0.02361, 0.35283, 0.93539}},
	{"cylinder 1 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8>", {1, 2, 3}, 16, 12, 1, 6, true, {-0.26455, -0.22780, 0.93710}},
	{"cylinder 2 location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.52905, 0.55950, 0.63800}},
	{"cylinder 2 location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.04152, 0.06535, 0.99701}},
	{"cylinder 2 location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.52905, -0.55950, 0.63800}},
	{"cylinder 2 location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.35036, 0.41427, 0.84002}},
	{"cylinder 2 location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.47536, -0.05754, 0.87790}},
	{"cylinder 2 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8> angle 70", {1, 2, 3}, 16, 12, 0, 0, true, {-0.25148, 0.30065, 0.91998}},
	{"cylinder 2 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8> angle 70", {1, 2, 3}, 16, 12, 8, 5, true, {0.41118, -0.13216, 0.90192}},
	{"cylinder 2 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8> angle 70", {1, 2, 3}, 16, 12, 15, 11, true, {0.75766, -0.55373, 0.34545}},
	{"cylinder 2 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8> angle 70", {1, 2, 3}, 16, 12, 3, 2, true, {-0.02382, 0.15837, 0.98709}},
	{"cylinder 2 location <1,2,3> up 2*y right 1.5*x look_at <3,1,8> angle 70", {1, 2, 3}, 16, 12, 1, 6, true, {-0.17470, -0.19841, 0.96442}},
	{"location 0 right -2*x up 0.5*y direction 3*z look_at -y", {0, 0, 0}, 8, 6, 0, 0, true, {-0.27938, -0.95789, -0.06651}},
	{"location 0 right -2*x up 0.5*y direction 3*z look_at -y", {0, 0, 0}, 8, 6, 4, 2, true, {0.04164, -0.99902, -0.01387}},
	{"location 0 right -2*x up 0.5*y direction 3*z look_at -y", {0, 0, 0}, 8, 6, 7, 5, true, {0.27938, -0.95789, 0.06651}},
	{"location 0 right -2*x up 0.5*y direction 3*z look_at -y", {0, 0, 0}, 8, 6, 3, 2, true, {-0.04161, -0.99902, -0.01387}},
	{"location 0 right -2*x up 0.5*y direction 3*z look_at -y", {0, 0, 0}, 8, 6, 1, 3, true, {-0.20394, -0.97888, 0.01360}},
	{"perspective location <1,2,3> look_at <3,1,8> right -1.33*x angle 100 rotate <10,20,30> translate -x", {1, 2, 3}, 16, 12, 0, 0, true, {0.67333, 0.73071, 0.11263}},
	{"perspective location <1,2,3> look_at <3,1,8> right -1.33*x angle 100 rotate <10,20,30> translate -x", {1, 2, 3}, 16, 12, 8, 5, true, {0.64990, 0.06230, 0.75747}},
	{"perspective location <1,2,3> look_at <3,1,8> right -1.33*x angle 100 rotate <10,20,30> translate -x", {1, 2, 3}, 16, 12, 15, 11, true, {0.17122, -0.69873, 0.69461}},
	{"perspective location <1,2,3> look_at <3,1,8> right -1.33*x angle 100 rotate <10,20,30> translate -x", {1, 2, 3}, 16, 12, 3, 2, true, {0.73953, 0.60000, 0.30513}},
	{"perspective location <1,2,3> look_at <3,1,8> right -1.33*x angle 100 rotate <10,20,30> translate -x", {1, 2, 3}, 16, 12, 1, 6, true, {0.96271, 0.26983, 0.01976}},
	{"fisheye orthographic perspective location <1,2,3> scale <1,2,1>", {1, 2, 3}, 16, 12, 0, 0, true, {-0.41707, 0.61523, 0.66897}},
	{"fisheye orthographic perspective location <1,2,3> scale <1,2,1>", {1, 2, 3}, 16, 12, 8, 5, true, {0.04137, 0.08495, 0.99551}},
	{"fisheye orthographic perspective location <1,2,3> scale <1,2,1>", {1, 2, 3}, 16, 12, 15, 11, true, {0.41808, -0.61276, 0.67062}},
	{"fisheye orthographic perspective location <1,2,3> scale <1,2,1>", {1, 2, 3}, 16, 12, 3, 2, true, {-0.30715, 0.48101, 0.82116}},
	{"fisheye orthographic perspective location <1,2,3> scale <1,2,1>", {1, 2, 3}, 16, 12, 1, 6, true, {-0.47414, -0.07112, 0.87756}},
	{"fisheye location <1,2,3> look_at <3,1,8> angle 270 rotate 30*y translate <0.5,0.2,0>", {1, 2, 3}, 16, 12, 0, 0, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location <1,2,3> look_at <3,1,8> angle 270 rotate 30*y translate <0.5,0.2,0>", {1, 2, 3}, 16, 12, 8, 5, true, {0.89126, 0.01518, 0.45321}},
	{"fisheye location <1,2,3> look_at <3,1,8> angle 270 rotate 30*y translate <0.5,0.2,0>", {1, 2, 3}, 16, 12, 15, 11, false, {-1.00000, -1.00000, -1.00000}},
	{"fisheye location <1,2,3> look_at <3,1,8> angle 270 rotate 30*y translate <0.5,0.2,0>", {1, 2, 3}, 16, 12, 3, 2, true, {-0.79022, 0.58962, 0.16701}},
	{"fisheye location <1,2,3> look_at <3,1,8> angle 270 rotate 30*y translate <0.5,0.2,0>", {1, 2, 3}, 16, 12, 1, 6, false, {-1.00000, -1.00000, -1.00000}},
	{"cylinder 3 location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.67156, 0.00047, 0.74096}},
	{"cylinder 3 location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.04906, 0.00005, 0.99881}},
	{"cylinder 3 location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.67156, -0.00047, 0.74096}},
	{"cylinder 3 location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.42754, 0.00029, 0.90399}},
	{"cylinder 3 location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.59570, -0.00005, 0.80322}},
	{"cylinder 4 location 0", {0, 0, 0}, 16, 12, 0, 0, true, {-0.00063, 0.65936, 0.75183}},
	{"cylinder 4 location 0", {0, 0, 0}, 16, 12, 8, 5, true, {0.00005, 0.06542, 0.99786}},
	{"cylinder 4 location 0", {0, 0, 0}, 16, 12, 15, 11, true, {0.00063, -0.65936, 0.75183}},
	{"cylinder 4 location 0", {0, 0, 0}, 16, 12, 3, 2, true, {-0.00038, 0.44228, 0.89688}},
	{"cylinder 4 location 0", {0, 0, 0}, 16, 12, 1, 6, true, {-0.00053, -0.06542, 0.99786}},
};

/* Every camera kind: the direction of the ray through a pixel's centre,
 * or no ray where POV-Ray's image is black. */
static void test_directions(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof dir_cases / sizeof dir_cases[0]; i++) {
		const struct dir_case *k = &dir_cases[i];
		struct camera c = parse_cam(k->cam);
		struct ray r;
		bool got = camera_ray(&c, k->px + 0.5, k->py + 0.5, k->w, k->h, 0, 0, &r);
		if (got != k->ray)
			fail_msg("camera { %s } pixel (%d, %d): %s, POV-Ray %s", k->cam, k->px, k->py,
			         got ? "a ray" : "no ray", k->ray ? "a ray" : "black");
		if (!got)
			continue;
		/* Where the ray leaves the sphere, as a unit vector from its
		 * centre (the ray starts inside). */
		vec3 oc = v3_sub(r.org, k->centre);
		double b = v3_dot(oc, r.dir), cc = v3_dot(oc, oc) - 1e6;
		double t = -b + sqrt(b * b - cc);
		vec3 hit = v3_scale(v3_madd(oc, r.dir, t), 1e-3);
		for (int a = 0; a < 3; a++) {
			double v = a == 0 ? hit.x : a == 1 ? hit.y : hit.z;
			if (fabs(v - k->d[a]) > 1e-4)
				fail_msg("camera { %s } pixel (%d, %d) axis %d: %.6f, POV-Ray %.5f", k->cam, k->px,
				         k->py, a, v, k->d[a]);
		}
	}
}

struct hit_case {
	const char *cam;
	int px, py;
	double pz;
	double xy[2];
};

/* 16x12 images. */
static const struct hit_case hit_cases[] = {
	{"cylinder 3 location 0", 0, 0, 10, {-9.0636, 0.4581}},
	{"cylinder 3 location 0", 8, 5, 10, {0.4910, 0.0418}},
	{"cylinder 3 location 0", 15, 11, 10, {9.0636, -0.4581}},
	{"cylinder 3 location 0", 3, 2, 10, {-4.7294, 0.2914}},
	{"cylinder 4 location 0", 0, 0, 10, {-0.6235, 8.7700}},
	{"cylinder 4 location 0", 8, 5, 10, {0.0418, 0.6552}},
	{"cylinder 4 location 0", 15, 11, 10, {0.6235, -8.7700}},
	{"cylinder 4 location 0", 3, 2, 10, {-0.3738, 4.9314}},
	{"cylinder 3 location <1,2,-3> up 2*y right 3*x angle 120", 0, 0, 0, {-3.4897, 2.9166}},
	{"cylinder 3 location <1,2,-3> up 2*y right 3*x angle 120", 8, 5, 0, {1.1966, 2.0835}},
	{"cylinder 3 location <1,2,-3> up 2*y right 3*x angle 120", 15, 11, 0, {5.4899, 1.0831}},
	{"cylinder 3 location <1,2,-3> up 2*y right 3*x angle 120", 3, 2, 0, {-1.0043, 2.5834}},
	{"cylinder 4 location <1,2,-3> up 2*y right 3*x angle 60", 0, 0, 0, {-0.4062, 3.5618}},
	{"cylinder 4 location <1,2,-3> up 2*y right 3*x angle 60", 8, 5, 0, {1.0935, 2.1311}},
	{"cylinder 4 location <1,2,-3> up 2*y right 3*x angle 60", 15, 11, 0, {2.4063, 0.4385}},
	{"cylinder 4 location <1,2,-3> up 2*y right 3*x angle 60", 3, 2, 0, {0.1559, 2.9459}},
	{"orthographic location <0,0,-10> look_at 0", 0, 0, 0, {-6.2345, 4.5835}},
	{"orthographic location <0,0,-10> look_at 0", 8, 5, 0, {0.4154, 0.4166}},
	{"orthographic location <0,0,-10> look_at 0", 15, 11, 0, {6.2345, -4.5835}},
	{"orthographic location <0,0,-10> look_at 0", 3, 2, 0, {-3.7406, 2.9166}},
	{"orthographic location <0,0,-10> look_at 0 right 4*x up 3*y", 0, 0, 0, {-1.8747, 1.3748}},
	{"orthographic location <0,0,-10> look_at 0 right 4*x up 3*y", 8, 5, 0, {0.1248, 0.1248}},
	{"orthographic location <0,0,-10> look_at 0 right 4*x up 3*y", 15, 11, 0, {1.8747, -1.3748}},
	{"orthographic location <0,0,-10> look_at 0 right 4*x up 3*y", 3, 2, 0, {-1.1252, 0.8750}},
	{"orthographic location <0,0,-10> look_at 0 angle 60", 0, 0, 0, {-5.4124, 3.9792}},
	{"orthographic location <0,0,-10> look_at 0 angle 60", 8, 5, 0, {0.3610, 0.3616}},
	{"orthographic location <0,0,-10> look_at 0 angle 60", 15, 11, 0, {5.4124, -3.9792}},
	{"orthographic location <0,0,-10> look_at 0 angle 60", 3, 2, 0, {-3.2474, 2.5321}},
	{"orthographic location <0,0,-10> look_at <0,0,-5>", 0, 0, 0, {-3.1174, 2.2916}},
	{"orthographic location <0,0,-10> look_at <0,0,-5>", 8, 5, 0, {0.2078, 0.2084}},
	{"orthographic location <0,0,-10> look_at <0,0,-5>", 15, 11, 0, {3.1174, -2.2916}},
	{"orthographic location <0,0,-10> look_at <0,0,-5>", 3, 2, 0, {-1.8705, 1.4585}},
	{"orthographic location <0,0,-10>", 0, 0, 0, {-6.8577, 5.0419}},
	{"orthographic location <0,0,-10>", 8, 5, 0, {0.4575, 0.4581}},
	{"orthographic location <0,0,-10>", 15, 11, 0, {6.8577, -5.0419}},
	{"orthographic location <0,0,-10>", 3, 2, 0, {-4.1147, 3.2084}},
	{"orthographic location <0,0,-10> right 4*x up 3*y angle 60 look_at 0", 0, 0, 0, {-5.4124, 3.9695}},
	{"orthographic location <0,0,-10> right 4*x up 3*y angle 60 look_at 0", 8, 5, 0, {0.3610, 0.3610}},
	{"orthographic location <0,0,-10> right 4*x up 3*y angle 60 look_at 0", 15, 11, 0, {5.4124, -3.9695}},
	{"orthographic location <0,0,-10> right 4*x up 3*y angle 60 look_at 0", 3, 2, 0, {-3.2474, 2.5260}},
	{"orthographic location <0,0,-10> right 4*x look_at 0", 0, 0, 0, {-1.8747, 0.4581}},
	{"orthographic location <0,0,-10> right 4*x look_at 0", 8, 5, 0, {0.1248, 0.0418}},
	{"orthographic location <0,0,-10> right 4*x look_at 0", 15, 11, 0, {1.8747, -0.4581}},
	{"orthographic location <0,0,-10> right 4*x look_at 0", 3, 2, 0, {-1.1252, 0.2914}},
	{"orthographic location <1,2,-10> look_at <1,2,0> rotate z*20", 0, 0, 0, {-7.1702, 4.3961}},
	{"orthographic location <1,2,-10> look_at <1,2,0> rotate z*20", 8, 5, 0, {0.5039, 2.7549}},
	{"orthographic location <1,2,-10> look_at <1,2,0> rotate z*20", 15, 11, 0, {7.6817, 0.0467}},
	{"orthographic location <1,2,-10> look_at <1,2,0> rotate z*20", 3, 2, 0, {-4.2570, 3.6826}},
	{"orthographic location <1,2,-10> direction 2*z angle 40", 0, 0, 0, {-2.8299, 4.8161}},
	{"orthographic location <1,2,-10> direction 2*z angle 40", 8, 5, 0, {1.2552, 2.2562}},
	{"orthographic location <1,2,-10> direction 2*z angle 40", 15, 11, 0, {4.8301, -0.8157}},
	{"orthographic location <1,2,-10> direction 2*z angle 40", 3, 2, 0, {-1.2979, 3.7919}},
};

/* Cameras whose rays start away from the location (orthographic, cylinder
 * 3 and 4) and the orthographic view's size (right and up, or the view of
 * a perspective camera at the look_at point, default look_at <0,0,1>):
 * where each ray meets the plane z = pz. */
static void test_origins(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof hit_cases / sizeof hit_cases[0]; i++) {
		const struct hit_case *k = &hit_cases[i];
		struct camera c = parse_cam(k->cam);
		struct ray r;
		assert_true(camera_ray(&c, k->px + 0.5, k->py + 0.5, 16, 12, 0, 0, &r));
		double t = (k->pz - r.org.z) / r.dir.z;
		double x = r.org.x + t * r.dir.x, y = r.org.y + t * r.dir.y;
		if (fabs(x - k->xy[0]) > 2e-3 || fabs(y - k->xy[1]) > 2e-3)
			fail_msg("camera { %s } pixel (%d, %d): (%.4f, %.4f), POV-Ray (%.4f, %.4f)", k->cam, k->px,
			         k->py, x, y, k->xy[0], k->xy[1]);
	}
}

/* The parser's defaults and order rules. */
static void test_parse_items(void **state)
{
	(void)state;
	struct camera c = parse_cam("perspective");
	assert_int_equal(c.kind, CAMERA_PERSPECTIVE);
	assert_near(c.confidence, 0.9, 0);
	assert_near(c.variance, 1.0 / 128, 0);
	assert_near(c.aperture, 0, 0);
	/* blur_samples N: the minimum is 4 below 7, else 7 (POV-Ray's ray
	 * counts on a uniform scene: blur_samples 3, 6, 7, 20 take 3, 4, 7,
	 * 7 rays per pixel). */
	c = parse_cam("aperture 1 blur_samples 20");
	assert_int_equal(c.blur_samples_min, 7);
	assert_int_equal(c.blur_samples_max, 20);
	c = parse_cam("aperture 1 blur_samples 6");
	assert_int_equal(c.blur_samples_min, 4);
	c = parse_cam("aperture 1 blur_samples 3");
	assert_int_equal(c.blur_samples_min, 3);
	c = parse_cam("aperture 1 blur_samples 10, 20");
	assert_int_equal(c.blur_samples_min, 10);
	assert_int_equal(c.blur_samples_max, 20);
	c = parse_cam("aperture 1 blur_samples 10 20.7");
	assert_int_equal(c.blur_samples_max, 20);
	/* cylinder 2.7 is type 2, as POV-Ray truncates. */
	c = parse_cam("cylinder 2.7");
	assert_int_equal(c.kind, CAMERA_CYLINDER);
	assert_int_equal(c.cylinder_type, 2);
	/* Several type keywords: the last counts. */
	c = parse_cam("fisheye orthographic");
	assert_int_equal(c.kind, CAMERA_ORTHOGRAPHIC);
	/* An out-of-range confidence is a warning and the default. */
	c = parse_cam("confidence 1");
	assert_near(c.confidence, 0.9, 0);
	/* spherical's vertical angle: half the horizontal unless given;
	 * `angle 100 -50` is one expression (50). */
	c = parse_cam("spherical angle 100 -50");
	assert_near(c.angle, 50, 0);
	assert_true(c.v_angle < 0);
	c = parse_cam("spherical angle 100, 40");
	assert_near(c.v_angle, 40, 0);
	/* Order does not matter: angle after right still uses that right. */
	struct camera a = parse_cam("angle 60 right 2*x"), b = parse_cam("right 2*x angle 60");
	assert_vec_near(a.direction, b.direction.x, b.direction.y, b.direction.z, 1e-12);
	assert_near(v3_len(a.direction), 1 / tan(M_PI / 6), 1e-12);
	/* A declared camera moved by a transformation. */
	c = parse_cam("location <1,2,3> } #declare C = camera { location <1,2,3> } camera { C translate x");
	assert_vec_near(c.location, 2, 2, 3, 1e-12);
}

/* Focal blur geometry: lens samples move the origin by aperture/2 times
 * the sample (so POV-Ray's lens radius aperture/4 for samples in the disc
 * of radius 1/2) and keep the point in focus: measured in POV-Ray, an
 * edge at z = 11 seen with aperture 0.4 and focus at z = 1 blurs over
 * 18.2 px of a 200 px wide image (0.1 * (1 - 1/11) of the width). */
static void test_lens(void **state)
{
	(void)state;
	struct camera c = parse_cam("location 0 direction z right x up y aperture 0.4 focal_point <0,0,1> "
	                            "blur_samples 10");
	struct ray p, r;
	assert_true(camera_ray(&c, 37.5, 61.5, 200, 200, 0, 0, &p));
	assert_true(camera_ray(&c, 37.5, 61.5, 200, 200, 0.5, 0, &r));
	assert_vec_near(r.org, 0.1, 0, 0, 1e-12);
	/* Both pass through the pinhole ray's point on the plane z = 1. */
	double tp = 1 / p.dir.z, tr = (1 - r.org.z) / r.dir.z;
	assert_near(p.org.x + tp * p.dir.x, r.org.x + tr * r.dir.x, 1e-12);
	assert_near(p.org.y + tp * p.dir.y, r.org.y + tr * r.dir.y, 1e-12);
	/* The edge x = 0 at z = 11: seen from the lens' rim at +0.1, the
	 * image position u where the ray reaches it is -0.1 * (1 - 1/11). */
	double u = -0.1 * (1 - 1.0 / 11);
	assert_true(camera_ray(&c, (u + 0.5) * 200, 100, 200, 200, -0.5, 0, &r));
	double t = (11 - r.org.z) / r.dir.z;
	assert_near(r.org.x + t * r.dir.x, 0, 1e-9);
}

/* The quad of the mesh-camera tests: 4 x 2 in the plane z = 0, uv the
 * unit square, faces turning clockwise in uv (their rays go along +z),
 * vertex normals leaning out by 0.3 in x. "} ... camera {" puts the
 * declaration before the camera block. */
#define MESH_QUAD                                                                                            \
	"} #declare M = mesh2 { vertex_vectors { 4, <-2,-1,0>, <2,-1,0>, <2,1,0>, <-2,1,0> } "                \
	"normal_vectors { 4, <-0.3,0,1>, <0.3,0,1>, <0.3,0,1>, <-0.3,0,1> } "                                 \
	"uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> } face_indices { 2, <0,2,1>, <0,3,2> } } camera { "

/* Where the ray of pixel (px, py) of a w x h image meets the plane z = 5. */
static double mesh_hit_x(const struct camera *c, int px, int py, int w, int h)
{
	struct ray r;
	assert_true(camera_mesh_ray(c, px + 0.5, py + 0.5, w, h, 0, &r));
	return r.org.x + (5 - r.org.z) / r.dir.z * r.dir.x;
}

/* Mesh camera, distribution 3: the ray of each pixel, smooth or not, and
 * max_distance. Measured in POV-Ray (6 x 3 and 4 x 4, no antialiasing,
 * File_Gamma 1, 16-bit PPM) looking at the plane z = 5 with pigment
 * gradient x scaled 8 and moved -4 (value (x + 4) / 8), middle row. */
static void test_mesh_camera(void **state)
{
	(void)state;
	struct camera c = parse_cam(MESH_QUAD "mesh_camera { 1 3 mesh { M } } location <0,0,1>");
	assert_int_equal(c.kind, CAMERA_MESH);
	assert_true(isinf(camera_ray_limit(&c)));
	/* Flat: POV-Ray's row 0.25 0.375 0.5 0.5625 at 4 x 4 (8-bit sRGB
	 * 137 165 188 198); location's z moves the origin 1 along the ray. */
	static const double flat[4] = {0.25, 0.375, 0.5, 0.5625};
	for (int i = 0; i < 4; i++)
		assert_near((mesh_hit_x(&c, i, 1, 4, 4) + 4) / 8, flat[i], 1e-4);
	struct ray r;
	assert_true(camera_mesh_ray(&c, 0.5, 1.5, 4, 4, 0, &r));
	assert_vec_near(r.org, -2, 0.5, 1, 1e-12);
	assert_vec_near(r.dir, 0, 0, 1, 1e-12);
	camera_clear(&c);
	/* Smooth: the normals interpolated. */
	c = parse_cam(MESH_QUAD "mesh_camera { 1 3 mesh { M } smooth }");
	static const double smooth[6] = {0.06250, 0.20833, 0.35416, 0.50001, 0.64584, 0.71875};
	for (int i = 0; i < 6; i++)
		assert_near((mesh_hit_x(&c, i, 1, 6, 3) + 4) / 8, smooth[i], 1e-4);
	camera_clear(&c);
	/* max_distance: 3.9 sees the background and 4.1 the plane from the
	 * origin moved 1 along the ray; 0 and below set no limit. */
	c = parse_cam(MESH_QUAD "mesh_camera { 1 3 4.1 mesh { M } } location <0,0,1>");
	assert_near(camera_ray_limit(&c), 4.1, 0);
	camera_clear(&c);
	c = parse_cam(MESH_QUAD "mesh_camera { 1 3 -1 mesh { M } }");
	assert_true(isinf(camera_ray_limit(&c)));
	camera_clear(&c);
	c = parse_cam("location 0");
	assert_true(isinf(camera_ray_limit(&c)));
}

/* Distributions 0 to 2: which faces a pixel's rays leave from. Face i of
 * mesh A lies at x = i, of mesh B at x = 16 + i, all facing +z; POV-Ray
 * (4 x 3, no antialiasing, 16-bit linear PPM) looked at the plane z = 5
 * with pigment gradient x scaled 32, so each pixel holds the mean x of
 * its rays' faces over 32. The tables give that mean x, row by row. */
struct dist_case {
	const char *cam;
	double x[12];
};

/* Declares mesh A of NA faces at x = 0.. and B of NB at x = 16.. */
#define MESH_FACES(NA, NB)                                                                                   \
	"} #macro Faces(N, X0) mesh { #for (I, 0, N - 1) triangle { <X0 + I - 0.2, -0.2, 0>, "                  \
	"<X0 + I, 0.2, 0>, <X0 + I + 0.2, -0.2, 0> } #end } #end "                                             \
	"#declare A = Faces(" #NA ", 0) #declare B = Faces(" #NB ", 16) camera { "

static const struct dist_case dist_cases[] = {
	/* The first two rows share the first row of faces. */
	{MESH_FACES(12, 12) "mesh_camera { 1 0 mesh { A } }", {0, 1, 2, 3, 0, 1, 2, 3, 4, 5, 6, 7}},
	/* Ray k from mesh k, averaged. */
	{MESH_FACES(12, 9) "mesh_camera { 2 0 mesh { A } mesh { B } }",
	 {8, 9, 10, 11, 8, 9, 10, 11, 12, 13, 14, 15}},
	/* One list of faces; the second ray is never shot. */
	{MESH_FACES(6, 6) "mesh_camera { 2 1 mesh { A } mesh { B } }",
	 {0, 1, 2, 3, 0, 1, 2, 3, 4, 5, 16, 17}},
	{MESH_FACES(5, 6) "mesh_camera { 1 1 mesh { A } mesh { B } }",
	 {0, 1, 2, 3, 0, 1, 2, 3, 4, 16, 17, 18}},
	/* Side by side, the face index counting the image's column. */
	{MESH_FACES(6, 6) "mesh_camera { 1 2 mesh { A } mesh { B } }",
	 {0, 1, 18, 19, 0, 1, 18, 19, 2, 3, 20, 21}},
};

static void test_mesh_distributions(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof dist_cases / sizeof dist_cases[0]; i++) {
		const struct dist_case *k = &dist_cases[i];
		struct camera c = parse_cam(k->cam);
		for (int py = 0; py < 3; py++)
			for (int px = 0; px < 4; px++) {
				double sum = 0;
				int n = 0;
				for (int ray = 0; ray < c.mesh->rays; ray++) {
					struct ray r;
					if (!camera_mesh_ray(&c, px + 0.5, py + 0.5, 4, 3, ray, &r))
						continue;
					assert_vec_near(r.dir, 0, 0, 1, 1e-12);
					sum += r.org.x;
					n++;
				}
				assert_true(n > 0);
				if (fabs(sum / n - k->x[py * 4 + px]) > 1e-9)
					fail_msg("%s: pixel (%d, %d) x %g, POV-Ray %g", k->cam, px, py, sum / n, k->x[py * 4 + px]);
			}
		camera_clear(&c);
	}
}

/* look_at and the frame's handedness: right is flipped unless
 * (up x direction) . right > 0, so a handedness of 0 mirrors the image as
 * a left-handed one does. Measured in POV-Ray (3 x 3, plane y = 0 with
 * gradient x and z pigments repeating every 40 units, 16-bit linear):
 * where the top-left and top-right pixels' rays meet the plane, modulo 40. */
struct hand_case {
	const char *cam;
	double left[2], right[2]; /* (x, z) */
};

static const struct hand_case hand_cases[] = {
	{"orthographic location <0.5,10,0.5> look_at <0.5,0,0.5> right x*5 up z*5", {2.17, 2.17}, {-1.17, 2.17}},
	{"orthographic location <0.5,10,0.5> look_at <0.5,0,0.5> right x*5 up y*5", {-1.17, 2.17}, {2.17, 2.17}},
	{"orthographic location <0.5,10,0.5> look_at <0.5,0,0.5> right x*5 up z*5 direction y", {2.17, 2.17},
	 {-1.17, 2.17}},
	{"orthographic location <0.5,10,0.5> look_at <0.5,0,0.5> right x*5 up z*5 direction -y", {-1.17, 2.17},
	 {2.17, 2.17}},
	{"location <0.5,10,0.5> look_at <0.5,0,0.5> right x*5 up z*5", {17.17, 17.17}, {-16.17, 17.17}},
	{"location <0.5,10,0.5> look_at <3,0,0.5> right x*5 up z*5", {-6.64, 11.05}, {-6.64, -10.05}},
	{"location <0.5,10,0.5> look_at <3,0,0.5> right x*5 up y*5", {-6.64, -10.05}, {-6.64, 11.05}},
	{"location <0.5,10,0.5> look_at <3,0,0.5> right z*5 up y*5", {-6.64, 11.05}, {-6.64, -10.05}},
	{"location <0.5,10,0.5> look_at <3,0,0.5> right x*5 up y*5 direction x", {-6.64, 11.05}, {-6.64, -10.05}},
};

static void test_look_at_handedness(void **state)
{
	(void)state;
	for (size_t i = 0; i < sizeof hand_cases / sizeof hand_cases[0]; i++) {
		const struct hand_case *k = &hand_cases[i];
		struct camera c = parse_cam(k->cam);
		for (int side = 0; side < 2; side++) {
			struct ray r;
			assert_true(camera_ray(&c, side ? 2.5 : 0.5, 0.5, 3, 3, 0, 0, &r));
			double t = -r.org.y / r.dir.y;
			double x = r.org.x + t * r.dir.x, z = r.org.z + t * r.dir.z;
			const double *want = side ? k->right : k->left;
			/* The pigments repeat every 40 units. */
			double dx = remainder(x - want[0], 40), dz = remainder(z - want[1], 40);
			if (fabs(dx) > 0.01 || fabs(dz) > 0.01)
				fail_msg("camera { %s } %s pixel: (%.2f, %.2f), POV-Ray (%.2f, %.2f)", k->cam,
				         side ? "top-right" : "top-left", x, z, want[0], want[1]);
		}
	}
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_directions),
		cmocka_unit_test(test_origins),
		cmocka_unit_test(test_parse_items),
		cmocka_unit_test(test_lens),
		cmocka_unit_test(test_mesh_camera),
		cmocka_unit_test(test_mesh_distributions),
		cmocka_unit_test(test_look_at_handedness),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

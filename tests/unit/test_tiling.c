/* test_tiling.c: unit tests for the tiling pattern (src/pattern/tiling.c).
 *
 * The values at three points for each tiling were printed by POV-Ray 3.7.0:
 *   #declare G = function { pigment { tiling N color_map { [0 rgb 0] [1 rgb 1] } } }
 *   #debug str(G(x, 0, z).red, 0, 9)
 * (tilings 25 to 27 also far from the origin, where an aperiodic tiling
 * could drift; for 25 a point on the face and one in the bevel of each of
 * its six kinds of tile, a star's and a boat's concave corner, a point
 * 1e-9 off an edge, where the value stays 1e-6 inside its band, and the
 * origin, where POV-Ray gives 1). They went through POV-Ray's single-precision colours, hence the
 * tolerance of 1e-6. The hand-derived cases check the rule itself: tiling 1
 * is unit squares, 0 at a centre and 1 on an edge, rising linearly between
 * (the bevel is the square's inradius 0.5); y is ignored. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "pattern/pattern.h"

#include <math.h>
#include <stdio.h>

struct tcase {
	int n;
	struct { double x, z, v; } s[3];
};

static const struct tcase cases[] = {
	{1, {{0.3137, 0.7291, 0.458200008}, {-1.8412, 2.2719, 0.682399988}, {3.1071, -2.6533, 0.785799980}}},
	{2, {{0.3137, 0.7291, 0.265353918}, {-1.8412, 2.2719, 0.847117901}, {3.1071, -2.6533, 0.424783468}}},
	{3, {{0.3137, 0.7291, 0.839130878}, {-1.8412, 2.2719, 0.770676911}, {3.1071, -2.6533, 0.904349566}}},
	{4, {{0.3137, 0.7291, 0.785507858}, {-1.8412, 2.2719, 0.694235861}, {3.1071, -2.6533, 0.872466147}}},
	{5, {{0.3137, 0.7291, 0.595169306}, {-1.8412, 2.2719, 0.231411949}, {3.1071, -2.6533, 0.425988972}}},
	{6, {{0.3137, 0.7291, 0.686299980}, {-1.8412, 2.2719, 0.841199994}, {3.1071, -2.6533, 0.153300002}}},
	{7, {{0.3137, 0.7291, 0.530264199}, {-1.8412, 2.2719, 0.500000000}, {3.1071, -2.6533, 0.500000000}}},
	{8, {{0.3137, 0.7291, 0.687191665}, {-1.8412, 2.2719, 0.666666687}, {3.1071, -2.6533, 0.271700144}}},
	{9, {{0.3137, 0.7291, 0.666666687}, {-1.8412, 2.2719, 0.847117901}, {3.1071, -2.6533, 0.666666687}}},
	{10, {{0.3137, 0.7291, 0.458200008}, {-1.8412, 2.2719, 0.682399988}, {3.1071, -2.6533, 0.306600004}}},
	{11, {{0.3137, 0.7291, 0.790866673}, {-1.8412, 2.2719, 0.485399991}, {3.1071, -2.6533, 0.928600013}}},
	{12, {{0.3137, 0.7291, 0.790866673}, {-1.8412, 2.2719, 0.560800016}, {3.1071, -2.6533, 0.928600013}}},
	{13, {{0.3137, 0.7291, 0.723066688}, {-1.8412, 2.2719, 0.524698794}, {3.1071, -2.6533, 0.597636163}}},
	{14, {{0.3137, 0.7291, 0.233840004}, {-1.8412, 2.2719, 0.714819312}, {3.1071, -2.6533, 0.558581710}}},
	{15, {{0.3137, 0.7291, 0.229100004}, {-1.8412, 2.2719, 0.728100002}, {3.1071, -2.6533, 0.653299987}}},
	{16, {{0.3137, 0.7291, 0.000000000}, {-1.8412, 2.2719, 0.226465136}, {3.1071, -2.6533, 0.670417607}}},
	{17, {{0.3137, 0.7291, 0.166666836}, {-1.8412, 2.2719, 0.279899418}, {3.1071, -2.6533, 0.835208833}}},
	{18, {{0.3137, 0.7291, 0.686299980}, {-1.8412, 2.2719, 0.841199994}, {3.1071, -2.6533, 0.153300002}}},
	{19, {{0.3137, 0.7291, 0.559420586}, {-1.8412, 2.2719, 0.666666985}, {3.1071, -2.6533, 0.602899730}}},
	{20, {{0.3137, 0.7291, 0.559420586}, {-1.8412, 2.2719, 0.513784587}, {3.1071, -2.6533, 0.666666985}}},
	{21, {{0.3137, 0.7291, 0.742618799}, {-1.8412, 2.2719, 0.879578590}, {3.1071, -2.6533, 0.064309448}}},
	{22, {{0.3137, 0.7291, 0.279304266}, {-1.8412, 2.2719, 0.666666687}, {3.1071, -2.6533, 0.666666687}}},
	{23, {{0.3137, 0.7291, 0.180600002}, {-1.8412, 2.2719, 0.666666985}, {3.1071, -2.6533, 0.210092947}}},
	{24, {{0.3137, 0.7291, 0.108360000}, {-1.8412, 2.2719, 0.800000191}, {3.1071, -2.6533, 0.126055777}}},
	{25, {{6.5165935863, -8.9330350662, 0.000000000}, {165.3618088194, -235.1682785611, 0.012885146},
	      {15.7155256557, -25.6840958571, 0.166667670}}},
	{25, {{2.0420887231, 1.6557514046, 0.280154258}, {2.3534081322, 10.6698286350, 0.333334327},
	      {145.0721935564, 177.1161393394, 0.384742528}}},
	{25, {{-732.1214149237, 1504.8081123722, 0.500001013}, {28.5604541848, -2.7876006245, 0.620204508},
	      {2730.4365116909, 2256.2286144453, 0.666667640}}},
	{25, {{22.3444659262, -12.6416899352, 0.763994575}, {-0.7692398666, 2.2106727472, 0.953458905},
	      {-1.8, 0, 0.833334327}}},
	{25, {{5.6786, -0.478, 0.654365838}, {-4.88, -7.84, 0.724475265}, {0.688191, 0, 0.499998987}}},
	{25, {{0, 0, 1.000000000}, {0.5, 0, 0.059081387}, {0.68819096, 1e-9, 0.166665673}}},
	{27, {{-5.2, 1e-9, 0.499998987}, {0, 0, 1.000000000}, {1e-8, 0, 0.499998987}}},
	{26, {{0.3137, 0.7291, 0.105704799}, {-1.8412, 2.2719, 0.918031156}, {3.1071, -2.6533, 0.000000000}}},
	{26, {{41.37, -28.91, 0.000000000}, {-77.3, 63.2, 0.312077105}, {0, 0.3, 0.293267638}}},
	{27, {{0.3137, 0.7291, 0.374729484}, {-1.8412, 2.2719, 0.729970336}, {3.1071, -2.6533, 0.219758824}}},
	{27, {{41.37, -28.91, 0.911266685}, {-77.3, 63.2, 0.327763677}, {0, 0.3, 0.341006637}}},
};

static double tiling_value(int n, double x, double y, double z)
{
	struct pattern pt = pattern_make(PAT_TILING);
	pt.n[0] = n;
	struct pattern_ctx ctx = {.p = v3(x, y, z), .normal = v3(0, 1, 0), .dir = v3(0, 0, 1)};
	double v = pattern_value(&pt, &ctx);
	pattern_clear(&pt);
	return v;
}

static void test_against_povray(void **state)
{
	(void)state;
	int bad = 0;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		for (int k = 0; k < 3; k++) {
			double v = tiling_value(cases[i].n, cases[i].s[k].x, 0, cases[i].s[k].z);
			if (fabs(v - cases[i].s[k].v) > 1e-6) {
				printf("tiling %d at (%g, %g): %.9f, POV-Ray %.9f\n", cases[i].n, cases[i].s[k].x,
				       cases[i].s[k].z, v, cases[i].s[k].v);
				bad++;
			}
		}
	}
	assert_int_equal(bad, 0);
}

/* tiling 1 by hand: unit squares [i, i+1] x [k, k+1]; the value is
 * 1 - d/0.5, d the distance from the nearest side. */
static void test_squares_by_hand(void **state)
{
	(void)state;
	assert_float_equal(tiling_value(1, 0.5, 0, 0.5), 0.0, 1e-12);
	assert_float_equal(tiling_value(1, 0.5, 0, 0.25), 0.5, 1e-12);
	assert_float_equal(tiling_value(1, 0.9, 0, 0.5), 0.8, 1e-12);
	assert_float_equal(tiling_value(1, -0.5, 0, -2.5), 0.0, 1e-12);
	assert_float_equal(tiling_value(1, 3.05, 0, 7.5), 0.9, 1e-12);
	/* y plays no part */
	assert_float_equal(tiling_value(1, 0.9, 17.3, 0.5), 0.8, 1e-12);
}

/* tiling 3 by hand: unit triangles with a horizontal edge on z = 0, those
 * pointing to +z of type 0 (values 0 to 0.5), the others of type 1 (0.5
 * to 1); the bevel is the inradius sqrt(3)/6 and the centres are at
 * 0 and 0.5. */
static void test_triangles_by_hand(void **state)
{
	(void)state;
	double r = sqrt(3.0) / 6;
	assert_float_equal(tiling_value(3, 0.5, 0, r), 0.0, 1e-12);
	assert_float_equal(tiling_value(3, 0.5, 0, -r), 0.5, 1e-12);
	assert_float_equal(tiling_value(3, 0.5, 0, r / 2), 0.25, 1e-12);
}

/* frequency acts on the value as for any continuous pattern */
static void test_frequency(void **state)
{
	(void)state;
	struct pattern pt = pattern_make(PAT_TILING);
	pt.n[0] = 1;
	pt.frequency = 2;
	struct pattern_ctx ctx = {.p = v3(0.5, 0, 0.1)};
	assert_float_equal(pattern_value(&pt, &ctx), fmod(0.8 * 2, 1.00001), 1e-9);
	pattern_clear(&pt);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_against_povray),
		cmocka_unit_test(test_squares_by_hand),
		cmocka_unit_test(test_triangles_by_hand),
		cmocka_unit_test(test_frequency),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

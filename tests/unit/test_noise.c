/* test_noise.c: POV-Ray's noise, turbulence, warps and noise patterns.
 *
 * Expected values were printed by POV-Ray 3.7.0.10 with
 *   #declare F = function { pattern { bozo noise_generator 2 } }
 *   #debug concat(str(F(x, y, z), 0, 10), "\n")
 * (and likewise for the other patterns and for warps applied to
 * `function { x*0.001+0.5 }`), unless a comment says otherwise. POV-Ray
 * prints 10 decimals; generators 1 and 2 and the patterns built on them are
 * expected to 1e-9. Generator 3, agate, ripples, waves, crackle and cells
 * use random tables of our own, so only their character is tested. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <cmocka.h>

#include "math/vec.h"
#include "pattern/kinds.h"
#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define TOL 1e-9

static void test_noise_generators_1_2(void **state)
{
	(void)state;
	/* along the x axis: the lattice values and the cubic blend between */
	assert_near(noise3(v3(0.0, 0, 0), 1), 0.0565805000, TOL);
	assert_near(noise3(v3(0.3, 0, 0), 1), 0.2494429304, TOL);
	assert_near(noise3(v3(1.5, 0, 0), 1), 0.4171970000, TOL);
	assert_near(noise3(v3(0.3, 0, 0), 2), 0.3927972233, TOL);
	assert_near(noise3(v3(1.9, 0, 0), 2), 0.3847723868, TOL);
	assert_near(noise3(v3(0.3, 0.7, 1.1), 2), 0.6895852173, TOL);
	/* negative coordinates */
	assert_near(noise3(v3(-0.3, 0.7, 1.1), 2), 0.6716474278, TOL);
	assert_near(noise3(v3(-0.3, 0, 0), 2), 0.2886817582, TOL);
	assert_near(noise3(v3(-1, 0, 0), 2), 0.5583232129, TOL);
	/* POV-Ray's period is 4096 on each axis, not 2048 */
	assert_near(noise3(v3(0.3 + 2048, 0.7, 1.1), 2), 0.5320568961, TOL);
	assert_near(noise3(v3(0.3 + 4096, 0.7, 1.1), 2), 0.6895852173, TOL);
	assert_near(noise3(v3(0.3, 0.7 + 4096, 1.1), 2), 0.6895852173, TOL);
}

/* Beyond a 32-bit int's range POV-Ray's lattice corner is INT_MIN and the
 * fraction huge, so the noise saturates at 0 or 1 (the fog of a ray that
 * misses everything, 1e10 away, shows it). Just inside the range the noise
 * is as usual. */
static void test_noise_beyond_int(void **state)
{
	(void)state;
	assert_near(noise3(v3(2147473648.3, 0.2, 0.7), 2), 0.4540588960, TOL);
	assert_near(noise3(v3(2147483647.3, 0.2, 0.7), 2), 0.5322910495, TOL);
	assert_near(noise3(v3(2147483647.3, 0.2, 0.7), 1), 0.5342079990, TOL);
	assert_near(noise3(v3(-2147483647.7, 0.2, 0.7), 2), 0.4610212112, TOL);
	assert_near(noise3(v3(-2147483647.7, 0.2, 0.7), 1), 0.3887165393, TOL);
	assert_near(noise3(v3(2147483648.3, 0.2, 0.7), 2), 0, TOL);
	assert_near(noise3(v3(-2147483648.7, 0.2, 0.7), 1), 0, TOL);
	assert_near(noise3(v3(2.2e9, 0.1, 0.2), 2), 1, TOL);
	assert_near(noise3(v3(1e10, 2e10, 3e10), 2), 1, TOL);
	assert_near(noise3(v3(-1e10, 2.3e10, -3e10), 2), 0, TOL);
	assert_near(noise3(v3(5e9, 1e9, 7e9), 1), 0, TOL);
	assert_near(noise3(v3(3e9, 3e9, 3e9), 1), 1, TOL);
	assert_near(noise3(v3(1e10, 1e10, -1e10), 2), 1, TOL);
}

static void test_noise_generator1_clips(void **state)
{
	(void)state;
	/* generator 2 is generator 1's unclipped sum mapped linearly: where
	 * generator 1 is inside (0, 1), g2 = (g1 + 0.55242) × 0.48985582 */
	int clipped = 0;
	for (int i = 0; i < 2000; i++) {
		vec3 p = v3(i * 0.731, i * 0.377 - 300, 50 - i * 0.113);
		double a = noise3(p, 1), b = noise3(p, 2);
		assert_true(a >= 0 && a <= 1);
		if (a > 0 && a < 1)
			assert_near(b, (a + 0.55242) * 0.48985582, 1e-12);
		else
			clipped++;
	}
	assert_true(clipped > 0);
}

static void stats(int gen, double *mean, double *sd, double *lo, double *hi)
{
	double s = 0, s2 = 0;
	*lo = 1, *hi = 0;
	int n = 0;
	for (int i = 0; i < 40; i++)
		for (int j = 0; j < 40; j++)
			for (int k = 0; k < 10; k++, n++) {
				double v = noise3(v3(i * 0.37 + 0.01, j * 0.41 - 7, k * 1.13 + 3), gen);
				s += v;
				s2 += v * v;
				if (v < *lo) *lo = v;
				if (v > *hi) *hi = v;
			}
	*mean = s / n;
	*sd = sqrt(s2 / n - *mean * *mean);
}

static void test_noise_character(void **state)
{
	(void)state;
	double mean, sd, lo, hi;
	/* POV-Ray over 20000 random points: gen 2 mean 0.506, sd 0.126, range
	 * [0.062, 0.922]; gen 3 mean 0.493, sd 0.146, range [0.013, 1] */
	stats(2, &mean, &sd, &lo, &hi);
	assert_near(mean, 0.506, 0.02);
	assert_near(sd, 0.126, 0.015);
	assert_true(lo > 0.05 && hi < 0.93);
	stats(3, &mean, &sd, &lo, &hi);
	assert_near(mean, 0.493, 0.03);
	assert_near(sd, 0.146, 0.03);
	/* generator 3 is a gradient noise: 0.4925 on its (shifted) lattice */
	double s = 0.0231572128;
	assert_near(noise3(v3(3 - s, 2 - s, 5 - s), 3), 0.4925, 1e-12);
	assert_near(noise3(v3(-7 - s, 11 - s, -s), 3), 0.4925, 1e-12);
	/* and it is deterministic */
	assert_true(noise3(v3(0.3, 0.2, 0.1), 3) == noise3(v3(0.3, 0.2, 0.1), 3));
}

/* Generator 3 exactly: POV-Ray's printed function { pattern { bozo
 * noise_generator 3 } } at random points (%.14f), near the origin and
 * thousands of units away; and the vector noise (turbulence), which is
 * generator 2's whatever the generator: warp { turbulence <0.1, 0, 0>
 * octaves 1 } on function { x } moved (0.7, 0.6, 0.55) to x = 0.695217575521
 * with noise_generator 1, 2 and 3 alike. */
static void test_generator3(void **state)
{
	(void)state;
	assert_near(noise3(v3(-17.6167235167, -34.9150826075, 15.0934473040), 3), 0.46750992743270, 1e-13);
	assert_near(noise3(v3(-42.7563713332, 3.5882004307, -13.4311083087), 3), 0.55830175686024, 1e-13);
	assert_near(noise3(v3(-44.2001075225, 0.7435733189, -46.2504341558), 3), 0.46880665133971, 1e-13);
	assert_near(noise3(v3(1956.5153930136, 2370.7836224522, -1514.9529419228), 3), 0.62570908241098, 1e-13);
	assert_near(noise3(v3(461.8158847928, -726.6748352275, -1224.1927104302), 3), 0.21563628845895, 1e-13);
	vec3 p = v3(0.7, 0.6, 0.55);
	for (int gen = 1; gen <= 3; gen++)
		assert_near(p.x + 0.1 * dnoise3(p, gen).x, 0.695217575521, 1e-12);
}

static void test_dnoise_and_turbulence(void **state)
{
	(void)state;
	/* warp { turbulence <0.1,0,0> octaves N } on function { x }, per
	 * component: the displacement divided by 0.1 */
	vec3 p = v3(-1.990242680949, -0.996345184608, 3.009379843240);
	assert_vec_near(dnoise3(p, 2), 0.4426424207, -0.1434270707, -0.1205449565, 1e-9);
	struct turbulence t = {{1, 1, 1}, 2, 0.5, 2.0};
	assert_vec_near(turbulence3(p, &t, 2), 0.5253990638, -0.0010913183, 0.0879994338, 1e-9);
	t.octaves = 6;
	assert_vec_near(turbulence3(p, &t, 2), 0.4194913577, 0.0636297279, -0.0830283625, 1e-9);
	/* omega in single precision: omega 0.7 lambda 3 octaves 3 */
	t.octaves = 3;
	t.omega = 0.7;
	t.lambda = 3;
	assert_vec_near(turbulence3(p, &t, 2), 0.8004039309, -0.6071260011, -0.3034148273, 1e-9);
	/* the x component of dnoise is the generator-1 sum less 0.5 */
	assert_near(dnoise3(v3(0.3, 0, 0), 2).x, 0.2494429304 - 0.5, 1e-9);
}

static struct pattern_ctx ctx_at(vec3 p)
{
	struct pattern_ctx c;
	memset(&c, 0, sizeof c);
	c.p = p;
	return c;
}

static double raw_at(const struct pattern *pt, vec3 p)
{
	struct pattern_ctx c = ctx_at(p);
	return pattern_raw(pt, pattern_point_ctx(pt, p, &c), &c);
}

/* POV-Ray's ramp wave as measured: fmod(v, 1.00001), negatives + 1. */
static double ramp(double v)
{
	v = fmod(v, 1.00001);
	return v < 0 ? v + 1 : v;
}

static void test_patterns_measured(void **state)
{
	(void)state;
	vec3 pts[3] = {v3(0.3, 0.7, 1.1), v3(-2.2, 1.35, 0.45), v3(3.7, -0.6, -1.9)};
	static const double granite[3] = {0.2445870639, 0.6117536314, 0.2969118697};
	static const double wrinkles[3] = {0.6968290582, 0.4111624061, 0.3355924566};
	static const double dents[3] = {0.3279169219, 0.1039256014, 0.0440952098};
	static const double marble_t[3] = {0.9915571006, 0.2030310237, 0.0270740521};
	static const double bozo_t[3] = {0.5280888525, 0.6656790722, 0.3079296780};
	struct pattern g = pattern_make(PAT_GRANITE), w = pattern_make(PAT_WRINKLES);
	struct pattern d = pattern_make(PAT_DENTS), m = pattern_make(PAT_MARBLE);
	struct pattern b = pattern_make(PAT_BOZO);
	m.has_turbulence = true;                /* marble turbulence 0.5 ramp_wave */
	m.turb.amount = v3(0.5, 0.5, 0.5);
	b.has_turbulence = true;                /* bozo turbulence 0.7 octaves 4 */
	b.turb.amount = v3(0.7, 0.7, 0.7);
	b.turb.octaves = 4;
	for (int i = 0; i < 3; i++) {
		assert_near(ramp(raw_at(&g, pts[i])), granite[i], TOL);
		assert_near(ramp(raw_at(&w, pts[i])), wrinkles[i], TOL);
		assert_near(raw_at(&d, pts[i]), dents[i], TOL);
		assert_near(ramp(raw_at(&m, pts[i])), marble_t[i], TOL);
		assert_near(raw_at(&b, pts[i]), bozo_t[i], TOL);
	}
	/* marble and wood without turbulence: x and the distance from the z axis */
	m.has_turbulence = false;
	assert_near(raw_at(&m, v3(2.654702, 1.439391, 2.53395)), 2.654702, 1e-12);
	struct pattern wd = pattern_make(PAT_WOOD);
	assert_near(raw_at(&wd, v3(3, 4, 9)), 5, 1e-12);
}

/* granite, wrinkles and marble's turbulence with noise_generator 1, as
 * POV-Ray 3.7.0 prints them for
 *   function { pattern { wrinkles noise_generator 1 } },
 *   { granite noise_generator 1 }, { marble turbulence 0.7 noise_generator 1 }
 * at these points (divided by 3 as in the scene); the last is a point
 * where the generator-1 noise clamps at 1. They use the noise itself
 * where generator 2 uses twice the noise less 0.5, clipped. */
static void test_generator1_patterns(void **state)
{
	(void)state;
	static const struct { double x, y, z, w, g, m; } c[] = {
		{2.031306, -9.361354, 9.918965, 0.5039597987, 0.3172673197, 0.7455978781},
		{5.792288, 3.218807, -4.152747, 0.4372805652, 0.2287096058, 0.9272388920},
		{-8.399916, 2.727385, -8.792391, 0.4535645259, 0.5544242093, 0.3537332160},
		{5.154232, 9.161627, 7.015720, 0.7545779428, 0.2807289623, 0.4785758032},
		{-2.082416, 1.627608, -4.395758, 0.5140616018, 0.6633787196, 0.0372135324},
	};
	struct pattern g = pattern_make(PAT_GRANITE), w = pattern_make(PAT_WRINKLES), m = pattern_make(PAT_MARBLE);
	g.noise_generator = w.noise_generator = m.noise_generator = 1;
	m.has_turbulence = true;
	m.turb.amount = v3(0.7, 0.7, 0.7);
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct pattern_ctx ctx = ctx_at(v3(c[i].x / 3, c[i].y / 3, c[i].z / 3));
		assert_near(pattern_value(&w, &ctx), c[i].w, TOL);
		assert_near(pattern_value(&g, &ctx), c[i].g, TOL);
		assert_near(pattern_value(&m, &ctx), c[i].m, TOL);
	}
	/* the first octave's noise clamped at 1 (raw 1.08): marble turbulence
	 * 0.5 octaves 1 adds 1/2 (POV-Ray: 0.0000500000, i.e. x + 0.5 wrapped
	 * by ramp_wave's 1.00001) */
	struct pattern m1 = pattern_make(PAT_MARBLE);
	m1.noise_generator = 1;
	m1.has_turbulence = true;
	m1.turb.amount = v3(0.5, 0.5, 0.5);
	m1.turb.octaves = 1;
	m1.wave = WAVE_RAMP;
	assert_near(raw_at(&m1, v3(5.154232, 9.161627, 7.015720)), 5.154232 + 0.5, 1e-9);
}

/* agate as POV-Ray 3.7.0 prints it for function { pattern { agate } },
 * { agate agate_turb 0.3 }, { agate turbulence 0.3 } and
 * { agate agate_turb 0.01 octaves 3 } (its own turbulence takes the
 * pattern's octaves; `turbulence` moves the point). */
static void test_agate_measured(void **state)
{
	(void)state;
	static const struct { double x, y, z, v[4]; } c[] = {
		{0.3, 0.7, 1.1, {0.6091121768, 0.0000613103, 0.7121282613, 0}},
		{-1.25, 0.4, 2.3, {0.3041154618, 0.4171510035, 0.3133504117, 0}},
		{0.05, -0.6, -0.35, {0.0260655935, 0.4835972691, 0.0169681402, 0}},
		{2.7, 1.3, -0.8, {0.3672281373, 0.4218382181, 0.0166465379, 0}},
		{2.031306 / 3, -9.361354 / 3, 9.918965 / 3, {-1, -1, -1, 0.166992157638}},
		{5.792288 / 3, 3.218807 / 3, -4.152747 / 3, {-1, -1, -1, 0.619534629642}},
	};
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		for (int k = 0; k < 4; k++) {
			if (c[i].v[k] < 0 || (k == 3) != (i >= 4))
				continue;
			struct pattern a = pattern_make(PAT_AGATE);
			a.f[0] = k == 1 ? 0.3 : k == 3 ? 0.01 : 1;
			if (k == 2) {
				a.has_turbulence = true;
				a.turb.amount = v3(0.3, 0.3, 0.3);
			}
			if (k == 3)
				a.turb.octaves = 3;
			struct pattern_ctx ctx = ctx_at(v3(c[i].x, c[i].y, c[i].z));
			assert_near(pattern_value(&a, &ctx), c[i].v[k], TOL);
		}
	}
}

static vec3 warp1(const struct pattern_op *op, vec3 p)
{
	struct pattern pt = pattern_make(PAT_BOZO);
	pattern_add_op(&pt, op);
	vec3 q = pattern_point(&pt, p);
	pattern_clear(&pt);
	return q;
}

static struct pattern_op op_of(enum pattern_op_kind k)
{
	struct pattern_op op;
	memset(&op, 0, sizeof op);
	op.kind = k;
	return op;
}

static void test_warp_repeat(void **state)
{
	(void)state;
	/* repeat 2*x offset <0,0.3,0.1> flip <1,1,0> */
	struct pattern_op op = op_of(POP_REPEAT);
	op.v1 = v3(2, 0, 0);
	op.v2 = v3(0, 0.3, 0.1);
	op.v3 = v3(1, 1, 0);
	assert_vec_near(warp1(&op, v3(-4.3, 0.2, 0.7)), 0.3, -1.1, 0.4, 1e-12);
	assert_vec_near(warp1(&op, v3(-2.5, 0.3, -0.2)), 1.5, -0.3, -0.4, 1e-12);
	assert_vec_near(warp1(&op, v3(2.1, 0.7, 0.25)), 1.9, -0.4, 0.35, 1e-12);
	assert_vec_near(warp1(&op, v3(2.0, 0.1, 0.1)), 2.0, 0.2, 0.2, 1e-12);
	assert_vec_near(warp1(&op, v3(0.5, 0.5, 0.3)), 0.5, 0.5, 0.3, 1e-12);
	/* repeat -2*x flip x: a negative width */
	op = op_of(POP_REPEAT);
	op.v1 = v3(-2, 0, 0);
	op.v3 = v3(1, 0, 0);
	assert_vec_near(warp1(&op, v3(-2.5, 0.3, -0.2)), -1.5, 0.3, -0.2, 1e-12);
	assert_vec_near(warp1(&op, v3(0.5, 0.5, 0.3)), -0.5, 0.5, 0.3, 1e-12);
	/* repeat <0,0,1.5> flip <0,1,1> offset <0.1,0.1,0.1> */
	op = op_of(POP_REPEAT);
	op.v1 = v3(0, 0, 1.5);
	op.v2 = v3(0.1, 0.1, 0.1);
	op.v3 = v3(0, 1, 1);
	assert_vec_near(warp1(&op, v3(-2.5, 0.3, -0.2)), -2.6, -0.4, 0.1, 1e-12);
	assert_vec_near(warp1(&op, v3(1.9, 0.6, -0.4)), 1.8, -0.7, 0.3, 1e-12);
}

static void test_warp_black_hole(void **state)
{
	(void)state;
	struct pattern_op op = op_of(POP_BLACK_HOLE);
	op.f1 = 1;      /* black_hole <0,0,0>, 1 */
	op.f2 = 2;
	op.f3 = 1;
	assert_vec_near(warp1(&op, v3(0.18, 0.24, 0)), 0.2682, 0.3576, 0, 1e-12);
	assert_vec_near(warp1(&op, v3(0.3, 0.2, 0.1)), 0.4175006, 0.2783337, 0.1391669, 1e-7);
	assert_vec_near(warp1(&op, v3(0.66, 0.88, 0)), 0.66, 0.88, 0, 1e-12);
	op.f4 = 1;      /* inverse */
	assert_vec_near(warp1(&op, v3(0.18, 0.24, 0)), 0.0918, 0.1224, 0, 1e-12);
	op.f3 = 3;      /* strength 3 inverse: the pull is capped at the centre */
	assert_vec_near(warp1(&op, v3(0.18, 0.24, 0)), 0, 0, 0, 1e-12);
	assert_vec_near(warp1(&op, v3(0.36, 0.48, 0)), 0.1872, 0.2496, 0, 1e-12);
	op.f4 = 0;      /* strength 2: the push is capped at twice the distance */
	op.f3 = 2;
	assert_vec_near(warp1(&op, v3(0.06, 0.08, 0)), 0.12, 0.16, 0, 1e-12);
}

static void test_warp_mappings(void **state)
{
	(void)state;
	vec3 p = v3(1.824137, 1.79131, -1.773795);
	struct pattern_op op = op_of(POP_CYLINDRICAL);
	op.v1 = v3(0, 0, 1);
	assert_vec_near(warp1(&op, p), 0.8772267, 1.79131, 2.5443711, 1e-7);
	op.v1 = v3(0, 1, 0);
	op.f1 = 1;
	assert_vec_near(warp1(&op, p), 2.2319904, -2.5443711, 1.79131, 1e-7);
	op = op_of(POP_SPHERICAL);
	op.v1 = v3(0, 0, 1);
	assert_vec_near(warp1(&op, p), 0.8772267, 0.6952591, 3.1116902, 1e-7);
	op.v1 = v3(1, 2, 3);    /* POV-Ray's skewed orientation matrix */
	op.f1 = 0.5;
	assert_vec_near(warp1(&op, p), 2.8994699, -0.3521532, 2.736893, 1e-6);
	op = op_of(POP_TOROIDAL);
	op.v1 = v3(0, 0, 1);
	op.f2 = 1;
	assert_vec_near(warp1(&op, p), 0.8772267, 0.6367607, 2.3651371, 1e-7);
	op.v1 = v3(0, 1, 0);
	op.f1 = 1;
	op.f2 = 1.5;
	assert_vec_near(warp1(&op, p), 1.8189509, -2.0735242, 1.3809494, 1e-7);
	op = op_of(POP_PLANAR);
	op.v1 = v3(0, 0, 1);
	assert_vec_near(warp1(&op, p), 1.824137, 1.79131, 0, 1e-12);
	op.v1 = v3(1, 1, 0);
	op.f1 = 0.5;
	assert_vec_near(warp1(&op, p), 1.643413, 0.9130941, -0.0232122, 1e-6);
}

/* warp { cubic }: POV-Ray 3.7 printed gradient x and gradient y through
 * the warp (u and v) at these points, faces and ties between faces
 * included; the third coordinate is the max-norm distance. */
static void test_warp_cubic(void **state)
{
	(void)state;
	static const double cases[][5] = {
		{1, .2, .3, 0.58750, 0.53333},   {-1, .2, .3, 0.16250, 0.53333}, {.2, 1, .3, 0.40000, 0.78333},
		{.2, -1, .3, 0.40000, 0.21667},  {.2, .3, 1, 0.40000, 0.55000},  {.2, .3, -1, 0.85000, 0.55000},
		{.1, .1, .05, 0.56250, 0.66667}, {.1, .05, .1, 0.50000, 0.58333}, {.05, .1, .1, 0.43750, 0.66667},
		{-.1, -.1, .05, 0.18750, 0.33333}, {.1, -.05, -.1, 0.75000, 0.41667}, {.05, -.1, -.1, 0.43750, 0.00000},
	};
	struct pattern_op op = op_of(POP_CUBIC);
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		const double *c = cases[i];
		double d = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
		assert_vec_near(warp1(&op, v3(c[0], c[1], c[2])), c[3], c[4], d, 6e-6);
	}
	vec3 q = warp1(&op, v3(0.25, 0.1, 0.1)); /* POV-Ray: gradient x 0.575, gradient z 0.25 */
	assert_true(fabs(q.x - 0.575) < 1e-9 && fabs(q.z - 0.25) < 1e-9);
}

static void test_warp_order(void **state)
{
	(void)state;
	/* warp { repeat 2*x } scale 2: the scale is undone first */
	struct pattern pt = pattern_make(PAT_BOZO);
	struct pattern_op op = op_of(POP_REPEAT);
	op.v1 = v3(2, 0, 0);
	pattern_add_op(&pt, &op);
	struct xform s = xform_scale(v3(2, 2, 2));
	pattern_transform(&pt, &s);
	assert_near(pattern_point(&pt, v3(-1.055808, 0, 0)).x, 1.472096, 1e-12);
	pattern_clear(&pt);
	/* classic turbulence is applied last, in pattern space: `scale 2
	 * turbulence 0.5 octaves 2` equals `warp { turbulence .. } scale 2` */
	struct pattern a = pattern_make(PAT_BOZO), b = pattern_make(PAT_BOZO);
	pattern_transform(&a, &s);
	a.has_turbulence = true;
	a.turb.amount = v3(0.5, 0.5, 0.5);
	a.turb.octaves = 2;
	op = op_of(POP_TURBULENCE);
	op.turb = a.turb;
	pattern_add_op(&b, &op);
	pattern_transform(&b, &s);
	vec3 p = v3(-1.055808, -1.587336, -0.415767), qa = pattern_point(&a, p), qb = pattern_point(&b, p);
	assert_vec_near(qa, qb.x, qb.y, qb.z, 1e-15);
	assert_near(qa.x, -0.451694, 1e-6);     /* POV-Ray: function { x*0.001+0.5 } */
	pattern_clear(&a);
	pattern_clear(&b);
}

/* cells and crackle at points printed by POV-Ray 3.7.0 for
 *   function { pattern { crackle } }, { crackle metric 1 },
 *   { crackle metric 3 form <0.5, 0.3, 0.2> }, { crackle form <0, 0, 1> offset 0.4 },
 *   { crackle metric 1 form <-1, 1, 0.5> offset 0.2 }, { crackle solid },
 *   { crackle solid noise_generator 1 scale 0.5 }, { cells scale 0.3 }
 * (the last point is one where metric 1's second-nearest point lies two
 * cubes away). Values above 1 are POV-Ray's clipping. */
static const struct { double x, y, z, v[8]; } crackle_cases[] = {
	{2.8378576815, 3.8539267038, 6.6831216534, {0.2789089535, 0.3156627769, 0.4949608438, 1.0000000000, 1.0000000000, 0.2643172952, 0.4997857451, 0.1909864468}},
	{-8.5141893147, 3.1051320427, 3.5927348848, {0.2190980682, 0.5084657436, 0.6583603890, 1.0000000000, 1.0000000000, 0.5026390753, 0.1266688240, 0.7010987585}},
	{8.7639896708, 0.4710720644, 9.5807406724, {0.4070296563, 0.4621292950, 0.5119224172, 0.9531894759, 1.0000000000, 0.5171373678, 0.3513216691, 0.3814895926}},
	{-5.1655600907, -0.8308073950, 6.5814241014, {0.1475529907, 0.1762934194, 0.4408655027, 0.7599075773, 0.7644304862, 0.4452694705, 0.3872149029, 0.5864633860}},
	{6.4599302636, -5.1964032033, -3.7652071085, {0.6336795093, 0.8403781408, 0.5108004707, 1.0000000000, 1.0000000000, 0.4968989596, 0.4557083356, 0.2278429393}},
	{9.4532641581, 1.3096058395, 7.0630326581, {0.3223975591, 0.3938924884, 0.5616182322, 0.9821173202, 1.0000000000, 0.6485511765, 0.5109945150, 0.1131925359}},
	{-9.2661919676, 8.9448801472, -5.0754060911, {0.0410619101, 0.2714962866, 0.7800962564, 1.0000000000, 1.0000000000, 0.4783634429, 0.0327992964, 0.7439744708}},
};

static void set_crackle_case(struct pattern *pt, int k)
{
	struct xform s;
	switch (k) {
	case 1: pt->f[0] = 1; break;
	case 2: pt->f[0] = 3; pt->form = v3(0.5, 0.3, 0.2); break;
	case 3: pt->form = v3(0, 0, 1); pt->f[1] = 0.4; break;
	case 4: pt->f[0] = 1; pt->form = v3(-1, 1, 0.5); pt->f[1] = 0.2; break;
	case 5: pt->n[0] = 1; break;
	case 6:
		pt->n[0] = 1;
		pt->noise_generator = 1;
		s = xform_scale(v3(0.5, 0.5, 0.5));
		pattern_transform(pt, &s);
		break;
	case 7:
		s = xform_scale(v3(0.3, 0.3, 0.3));
		pattern_transform(pt, &s);
		break;
	default: break;
	}
}

static void test_cells_crackle_povray(void **state)
{
	(void)state;
	int bad = 0;
	for (size_t i = 0; i < sizeof crackle_cases / sizeof crackle_cases[0]; i++) {
		for (int k = 0; k < 8; k++) {
			struct pattern pt = pattern_make(k == 7 ? PAT_CELLS : PAT_CRACKLE);
			set_crackle_case(&pt, k);
			struct pattern_ctx ctx = {.p = v3(crackle_cases[i].x, crackle_cases[i].y, crackle_cases[i].z)};
			double v = pattern_value(&pt, &ctx);
			if (fabs(v - crackle_cases[i].v[k]) > 1e-9) {
				printf("case %d at point %d: %.10f, POV-Ray %.10f\n", k, (int)i, v, crackle_cases[i].v[k]);
				bad++;
			}
			pattern_clear(&pt);
		}
	}
	assert_int_equal(bad, 0);
	/* a face belongs to the cube above it: POV-Ray 3.7.0's cells at
	 * (0.5, y, 0.5) is 0.7118189153 for y = 0 and -5e-11, 0.0965327462 for
	 * y = -2e-10 */
	struct pattern c = pattern_make(PAT_CELLS);
	struct pattern_ctx a = {.p = v3(0.5, -5e-11, 0.5)}, b = {.p = v3(0.5, -2e-10, 0.5)};
	assert_near(pattern_value(&c, &a), 0.7118189153, 1e-9);
	assert_near(pattern_value(&c, &b), 0.0965327462, 1e-9);
}

static void test_ripples_waves_character(void **state)
{
	(void)state;
	struct pattern r = pattern_make(PAT_RIPPLES), w = pattern_make(PAT_WAVES);
	for (int i = 0; i < 200; i++) {
		vec3 p = v3(i * 0.071, 0.3, i * 0.013);
		double a = raw_at(&r, p), b = raw_at(&w, p);
		assert_true(a >= 0 && a <= 1);
		assert_true(b >= 0 && b <= 1);
	}
}

/* ripples and waves as POV-Ray 3.7.0 renders them with 10 wave sources:
 * a plane at y = 0 seen from above (orthographic, 160 x 160 over
 * [-2, 3] x [-2, 3], an image POV-Ray mirrors in x: the points below are
 * the world points of the pixels) with pigment { K [frequency F phase P] color_map
 * { [0 rgb 0] [1 rgb 1] } }, ambient 1, written as a linear 16-bit PPM:
 * the values below are pixels of those images, so within 2/65535 plus
 * the sources' measurement error (6e-5 in all). The normals: plane { z, 0 }
 * seen from -z with normal { K 0.5 [frequency F phase P] }, solved from
 * three coloured lights as for bumps (test_special_normals), at
 * (0.03125, 0.96875, 0). */
static void test_ripples_waves_measured(void **state)
{
	(void)state;
	static const struct { enum pattern_kind k; double F, P; double v[3]; vec3 n; } c[] = {
		{PAT_RIPPLES, 1, 0, {0.5121843, 0.5704128, 0.3793240}, {0.01039, -0.22515, -0.97426}},
		{PAT_WAVES, 1, 0, {0.3769894, 0.6744488, 0.3390860}, {-0.13464, 0.18066, -0.97427}},
		{PAT_RIPPLES, 2, 0.3, {0.7712520, 0.2921493, 0.3875181}, {0.07367, -0.01793, -0.99710}},
		{PAT_WAVES, 0.7, 0.2, {0.4427558, 0.6098421, 0.4301976}, {-0.22773, 0.13565, -0.96422}},
	};
	static const vec3 pts[3] = {{2.890625, 0, 2.828125}, {0.578125, 0, -0.765625}, {-1.390625, 0, 1.953125}};
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct pattern pt = pattern_make(c[i].k);
		pt.frequency = c[i].F;
		pt.phase = c[i].P;
		for (int j = 0; j < 3; j++) {
			struct pattern_ctx ctx = ctx_at(pts[j]);
			assert_near(pattern_value(&pt, &ctx), c[i].v[j], 6e-5);
		}
		struct pattern_ctx ctx = ctx_at(v3(0.03125, 0.96875, 0));
		vec3 out;
		assert_true(pattern_special_normal(&pt, 0.5, ctx.p, v3(0, 0, -1), &ctx, &out));
		assert_vec_near(out, c[i].n.x, c[i].n.y, c[i].n.z, 4e-5);
		pattern_clear(&pt);
	}
}

/* ripples and waves to POV-Ray's printed digits: POV-Ray 3.7.0's
 *   #declare F = function { pattern { ripples } }   (and waves)
 *   #debug concat(str(F(x, y, z), 0, 16), "\n")
 * at random points (its first ten wave sources were fitted to 300 such
 * values, wave_sources.inc). */
static void test_ripples_waves_exact(void **state)
{
	(void)state;
	static const double c[][5] = {
		{-0.285723, 0.358634, 2.545264, 0.7991793230897866, 0.4513831025835261},
		{-0.2061, 0.047048, 0.524309, 0.7114684459881367, 0.7419058889913398},
		{-1.892038, 0.071452, 0.779296, 0.4030254248907793, 0.3088984131599550},
		{1.757861, -2.435259, -1.179592, 0.6386847570729439, 0.4015832847579525},
	};
	struct pattern r = pattern_make(PAT_RIPPLES), w = pattern_make(PAT_WAVES);
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		struct pattern_ctx ctx = ctx_at(v3(c[i][0], c[i][1], c[i][2]));
		assert_near(pattern_value(&r, &ctx), c[i][3], 1e-12);
		assert_near(pattern_value(&w, &ctx), c[i][4], 1e-12);
	}
}

/* number_of_waves (pattern_ctx.number_of_waves, from global_settings)
 * changes the sources of ripples and waves; 0 means POV-Ray's 10. */
static void test_number_of_waves(void **state)
{
	(void)state;
	struct pattern r = pattern_make(PAT_RIPPLES), w = pattern_make(PAT_WAVES);
	struct pattern_ctx c10 = {.p = v3(0.3, 0.4, 0.5)}, c3 = c10, c10b = c10;
	c3.number_of_waves = 3;
	c10b.number_of_waves = 10;
	assert_true(fabs(pattern_value(&r, &c10) - pattern_value(&r, &c3)) > 1e-6);
	assert_true(fabs(pattern_value(&w, &c10) - pattern_value(&w, &c3)) > 1e-6);
	assert_near(pattern_value(&r, &c10), pattern_value(&r, &c10b), 0);
}

static void test_special_normals(void **state)
{
	(void)state;
	/* (facets ignores the amount: test_facets_normal) */
	enum pattern_kind kinds[] = {PAT_BUMPS, PAT_DENTS, PAT_WRINKLES, PAT_RIPPLES, PAT_WAVES};
	vec3 n = v3(0, 1, 0);
	for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++) {
		struct pattern pt = pattern_make(kinds[i]);
		struct pattern_ctx c = ctx_at(v3(0.3, 0, 0.7));
		vec3 out;
		assert_true(pattern_special_normal(&pt, 0.5, c.p, n, &c, &out));
		assert_near(v3_len(out), 1, 1e-12);
		assert_true(out.y > 0);
		/* amount 0 leaves the normal alone */
		assert_true(pattern_special_normal(&pt, 0, c.p, n, &c, &out));
		assert_vec_near(out, 0, 1, 0, 1e-12);
	}
	/* POV-Ray's normals for plane { z, 0 } seen from -z with normal { N },
	 * at (0.03125, 0.96875, 0): rendered lit by three coloured parallel
	 * lights at <1,0,-1>, <0,1,-1>, <0,0,-1> (16-bit linear PPM) and solved
	 * for the normal, so within 3e-5 */
	static const struct { enum pattern_kind k; double sx, rz; vec3 want; } m[] = {
		{PAT_BUMPS, 1, 0, {-0.05582, -0.04792, -0.99727}},      /* bumps 0.5 */
		{PAT_DENTS, 1, 0, {-0.00568, -0.00488, -0.99995}},      /* dents 0.5 */
		{PAT_BUMPS, 0.5, 0, {-0.09130, -0.06377, -0.99376}},    /* bumps 0.5 scale <0.5, 1, 1> */
		{PAT_BUMPS, 1, 30, {0.04667, -0.29223, -0.95520}},      /* bumps 0.5 rotate 30*z */
		{PAT_WRINKLES, 1, 0, {0.19185, 0.15821, -0.96857}},    /* wrinkles 0.5 */
	};
	for (size_t i = 0; i < sizeof m / sizeof m[0]; i++) {
		struct pattern pt = pattern_make(m[i].k);
		struct xform t = xform_scale(v3(m[i].sx, 1, 1));
		if (m[i].rz != 0)
			t = xform_rotate(v3(0, 0, m[i].rz));
		pattern_transform(&pt, &t);
		struct pattern_ctx c = ctx_at(v3(0.03125, 0.96875, 0));
		c.noise_generator = 2;
		vec3 out;
		assert_true(pattern_special_normal(&pt, 0.5, c.p, v3(0, 0, -1), &c, &out));
		assert_vec_near(out, m[i].want.x, m[i].want.y, m[i].want.z, 3e-5);
		pattern_clear(&pt);
	}
	struct pattern g = pattern_make(PAT_GRANITE);
	struct pattern_ctx c = ctx_at(v3(0, 0, 0));
	vec3 out;
	assert_false(pattern_special_normal(&g, 0.5, c.p, n, &c, &out));
}

/* The facets normal against POV-Ray's: normal { facets ... } on
 * sphere { 0, 1.4 } and plane { <-0.3, 0.4, -1>, 0 } seen along +z by an
 * orthographic camera, lit by parallel shadowless lights along +-x, +-y and
 * +-z coloured red, green and blue (two renders, 16-bit linear PPM, diffuse
 * 1, brilliance 1), the normal read per pixel (so within 3e-5); p and n
 * are the pixel's point and unit normal. */
static void test_facets_normal(void **state)
{
	(void)state;
	static const struct {
		double size, coords, amount;
		int xf;        /* 1: scale <1, 2, 1>; 2: rotate 30*z */
		vec3 p, n, want;
	} m[] = {
		/* facets (size 0.1), facets 0.5 (the amount plays no part) */
		{0.1, 0, 1, 0, {-0.4875, 0.7375, -1.08555861196}, {-0.34821428571, 0.52678571429, -0.77539900854},
		 {-0.34171, 0.55775, -0.7564}},
		{0.1, 0, 0.5, 0, {0.3875, -0.3875, -1.288288593445}, {0.27678571429, -0.27678571429, -0.92020613817},
		 {0.3019, -0.23685, -0.92345}},
		/* facets size 0.3 */
		{0.3, 0, 1, 0, {0.5125, -0.5125, -1.197784412989}, {0.36607142857, -0.36607142857, -0.85556029499},
		 {0.32049, -0.29628, -0.89972}},
		/* facets coords 1 on the plane; facets 2 coords 1 */
		{0.1, 1, 1, 0, {-0.2375, 0.2375, 0.16625}, {-0.26832815730, 0.35777087640, -0.89442719100},
		 {-0.26635, 0.13379, -0.95454}},
		{0.1, 1, 2, 0, {-1.4875, -0.7625, 0.14125}, {-0.26832815730, 0.35777087640, -0.89442719100},
		 {-0.18656, 0.64558, -0.74055}},
		/* facets coords 1 scale <1, 2, 1> */
		{0.1, 1, 1, 1, {1.0125, 0.4875, -0.10875}, {-0.26832815730, 0.35777087640, -0.89442719100},
		 {-0.32532, 0.20407, -0.92332}},
		/* facets rotate 30*z on the sphere */
		{0.1, 0, 1, 2, {-0.7375, 0.4875, -1.08555861196}, {-0.52678571429, 0.34821428571, -0.77539900854},
		 {-0.57481, 0.31217, -0.7564}},
	};
	for (size_t i = 0; i < sizeof m / sizeof m[0]; i++) {
		struct pattern pt = pattern_make(PAT_FACETS);
		pt.vec = v3(m[i].size, m[i].coords, 0);
		if (m[i].xf) {
			struct xform t = m[i].xf == 1 ? xform_scale(v3(1, 2, 1)) : xform_rotate(v3(0, 0, 30));
			pattern_transform(&pt, &t);
		}
		struct pattern_ctx c = ctx_at(m[i].p);
		vec3 out;
		assert_true(pattern_special_normal(&pt, m[i].amount, c.p, m[i].n, &c, &out));
		assert_vec_near(out, m[i].want.x, m[i].want.y, m[i].want.z, 3e-5);
		pattern_clear(&pt);
	}
	/* metric 1 (the 81 cubes' point of smallest coordinate sum) and 0
	 * (their first point), measured the same way */
	static const struct { double metric, coords; vec3 p, n, want; } mm[] = {
		{1, 0, {-0.4875, 0.7375, -1.08555861196}, {-0.34821428571, 0.52678571429, -0.77539900854},
		 {-0.44378, 0.38163, -0.81082}},
		{1, 0, {0.2625, -0.2625, -1.349884254297}, {0.1875, -0.1875, -0.96420303878}, {0.02103, -0.27352, -0.96164}},
		{0, 1, {-0.2375, 0.4875, -1.290712012805}, {-0.16964285714, 0.34821428571, -0.92193715200},
		 {-0.16522, 0.29799, -0.94015}},
	};
	for (size_t i = 0; i < sizeof mm / sizeof mm[0]; i++) {
		struct pattern pt = pattern_make(PAT_FACETS);
		pt.vec.y = mm[i].coords;
		pt.f[0] = mm[i].metric;
		struct pattern_ctx c = ctx_at(mm[i].p);
		vec3 out;
		assert_true(pattern_special_normal(&pt, 1, c.p, mm[i].n, &c, &out));
		assert_vec_near(out, mm[i].want.x, mm[i].want.y, mm[i].want.z, 3e-5);
	}
	/* size 0 or less leaves the normal alone, as in POV-Ray */
	struct pattern pt = pattern_make(PAT_FACETS);
	pt.vec.x = -0.3;
	struct pattern_ctx c = ctx_at(v3(0.3, 0.2, 0.1));
	vec3 out;
	assert_true(pattern_special_normal(&pt, 1, c.p, v3(0, 0.6, -0.8), &c, &out));
	assert_vec_near(out, 0, 0.6, -0.8, 1e-15);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_noise_generators_1_2),
		cmocka_unit_test(test_noise_generator1_clips),
		cmocka_unit_test(test_noise_beyond_int),
		cmocka_unit_test(test_generator1_patterns),
		cmocka_unit_test(test_agate_measured),
		cmocka_unit_test(test_ripples_waves_measured),
		cmocka_unit_test(test_ripples_waves_exact),
		cmocka_unit_test(test_noise_character),
		cmocka_unit_test(test_generator3),
		cmocka_unit_test(test_dnoise_and_turbulence),
		cmocka_unit_test(test_patterns_measured),
		cmocka_unit_test(test_warp_repeat),
		cmocka_unit_test(test_warp_black_hole),
		cmocka_unit_test(test_warp_mappings),
		cmocka_unit_test(test_warp_cubic),
		cmocka_unit_test(test_warp_order),
		cmocka_unit_test(test_cells_crackle_povray),
		cmocka_unit_test(test_number_of_waves),
		cmocka_unit_test(test_ripples_waves_character),
		cmocka_unit_test(test_special_normals),
		cmocka_unit_test(test_facets_normal),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

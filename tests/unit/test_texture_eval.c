/* test_texture_eval.c: unit tests for pigment_eval and normal_eval
 * (src/scene/texture_eval.c): colour maps (ties, unsorted entries, all five
 * channels), the built-in maps and block lists POV-Ray uses when a pigment
 * has none, pigment maps, average, and the normal perturbations.
 *
 * The expected colours were printed by POV-Ray 3.7.0 with
 *   #declare G = function { pigment { SPEC } }
 *   #debug concat(vstr(5, G(x, y, z), " ", 0, 10), "\n")
 * (SPEC quoted beside each check). POV-Ray blends colours in single
 * precision, so they are compared to 1e-6. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "scene/texture.h"

#include <math.h>

static struct pattern_ctx ctx_at(double x, double y, double z)
{
	struct pattern_ctx c = {.p = {x, y, z}, .normal = {0, 1, 0}, .dir = {0, 0, 1}, .noise_generator = 2};
	return c;
}

static void check_color(struct rgbft c, double r, double g, double b, double f, double t)
{
	assert_true(fabs(c.r - r) < 1e-6);
	assert_true(fabs(c.g - g) < 1e-6);
	assert_true(fabs(c.b - b) < 1e-6);
	assert_true(fabs(c.f - f) < 1e-6);
	assert_true(fabs(c.t - t) < 1e-6);
}

static struct rgbft eval(const struct pigment *pg, double x, double y, double z)
{
	struct pattern_ctx c = ctx_at(x, y, z);
	return pigment_eval(pg, &c);
}

static struct pigment *pattern_pigment(enum pattern_kind k)
{
	struct pigment *pg = pigment_new();
	pg->kind = PIGMENT_PATTERN;
	pg->pat = pattern_make(k);
	return pg;
}

static struct rgbft col(double r, double g, double b, double f, double t)
{
	struct rgbft c = {r, g, b, f, t};
	return c;
}

/* A colour map of n entries (value, colour) pairs. */
static struct blend_map *color_map(int n, const double *v, const struct rgbft *c)
{
	struct blend_map *m = blend_map_new(MAP_COLOR, n);
	for (int i = 0; i < n; i++) {
		m->e[i].value = v[i];
		m->e[i].color = c[i];
	}
	return m;
}

static void test_default_maps(void **state)
{
	(void)state;
	/* gradient x: the grey ramp */
	struct pigment *g = pattern_pigment(PAT_GRADIENT);
	g->pat.vec = v3(1, 0, 0);
	check_color(eval(g, 0.3, 0, 0), 0.3000000119, 0.3000000119, 0.3000000119, 0, 0);
	check_color(eval(g, 1, 0, 0), 1, 1, 1, 0, 0);
	pigment_unref(g);
	/* radial: cyan, yellow at 0.333, magenta at 0.666, cyan */
	struct pigment *r = pattern_pigment(PAT_RADIAL);
	check_color(eval(r, -1, 0, 0), 1.0, 0.4984984994, 0.5015015006, 0, 0);
	check_color(eval(r, 0, 0, 1), 0.7485029697, 0.2514970005, 1.0, 0, 0);
	check_color(eval(r, 0, 0, 0), 0.7507507205, 1.0, 0.2492492795, 0, 0);
	pigment_unref(r);
	/* mandel 5 exterior 0, F at <3, 3, 0>: the value is F */
	struct pigment *m = pattern_pigment(PAT_MANDEL);
	m->pat.fractal.iterations = 5;
	m->pat.fractal.exterior_type = 0;
	m->pat.fractal.exterior_factor = 0.0015;
	check_color(eval(m, 3, 3, 0), 0.0454545431, 1.0, 0.9545454383, 0, 0);
	m->pat.fractal.exterior_factor = 0.0135;
	check_color(eval(m, 3, 3, 0), 1.0, 0.4999999404, 0.5000000596, 0, 0);
	m->pat.fractal.exterior_factor = 0.02;
	check_color(eval(m, 3, 3, 0), 0.9411764741, 0.0588235334, 1.0, 0, 0);
	m->pat.fractal.exterior_factor = 0.001;
	check_color(eval(m, 3, 3, 0), 0, 0, 0, 0, 0);
	m->pat.fractal.exterior_factor = 0.5;
	check_color(eval(m, 3, 3, 0), 0, 1, 1, 0, 0);
	pigment_unref(m);
}

static void test_block_defaults(void **state)
{
	(void)state;
	struct pigment *c = pattern_pigment(PAT_CHECKER);
	check_color(eval(c, 0.5, 0.5, 0.5), 0, 0, 1, 0, 0);
	check_color(eval(c, 1.5, 0.5, 0.5), 0, 1, 0, 0, 0);
	pigment_unref(c);
	struct pigment *h = pattern_pigment(PAT_HEXAGON);
	check_color(eval(h, 0, 0, 0), 0, 0, 1, 0, 0);
	check_color(eval(h, 0, 0, 1.7), 0, 1, 0, 0, 0);
	check_color(eval(h, 1.5, 0, 0.8), 1, 0, 0, 0, 0);
	pigment_unref(h);
	struct pigment *b = pattern_pigment(PAT_BRICK);
	check_color(eval(b, 1, 1, 1), 0.6000000238, 0.1500000060, 0.1500000060, 0, 0);
	check_color(eval(b, 1, 2.9, 1), 0.5, 0.5, 0.5, 0, 0);
	pigment_unref(b);
	struct pigment *k = pattern_pigment(PAT_CUBIC);
	check_color(eval(k, 1, 0, 0), 1, 0, 0, 0, 0);
	check_color(eval(k, -1, 0, 0), 1, 1, 0, 0, 0);
	check_color(eval(k, 0, -1, 0), 0, 1, 1, 0, 0);
	check_color(eval(k, 0, 0, -1), 1, 0, 1, 0, 0);
	pigment_unref(k);
}

static void test_color_map_lookup(void **state)
{
	(void)state;
	struct pigment *g = pattern_pigment(PAT_GRADIENT);
	g->pat.vec = v3(1, 0, 0);
	/* color_map { [0.3 red][0.3 blue][0.7 green] }: a tie takes the first
	 * entry at the value itself, the second just above it */
	const double v1[] = {0.3, 0.3, 0.7};
	const struct rgbft c1[] = {col(1, 0, 0, 0, 0), col(0, 0, 1, 0, 0), col(0, 1, 0, 0, 0)};
	g->map = color_map(3, v1, c1);
	check_color(eval(g, 0.2, 0, 0), 1, 0, 0, 0, 0);
	check_color(eval(g, 0.3, 0, 0), 1, 0, 0, 0, 0);
	check_color(eval(g, 0.30001, 0, 0), 0, 0.0000249702, 0.9999750257, 0, 0);
	check_color(eval(g, 0.8, 0, 0), 0, 1, 0, 0, 0);
	blend_map_unref(g->map);
	/* color_map { [0.5 red][0.2 blue][0.8 green] }: not sorted */
	const double v2[] = {0.5, 0.2, 0.8};
	g->map = color_map(3, v2, c1);
	g->map->e[2].color = col(0, 1, 0, 0, 0);
	check_color(eval(g, 0.3, 0, 0), 1, 0, 0, 0, 0);
	check_color(eval(g, 0.6, 0, 0), 0, 0.6666666269, 0.3333333731, 0, 0);
	blend_map_unref(g->map);
	/* color_map { [0.2 rgbft <1,0,0,0.5,0.2>][0.6 rgbft <0,0,1,0,1>] } */
	const double v3v[] = {0.2, 0.6};
	const struct rgbft c3[] = {col(1, 0, 0, 0.5, 0.2), col(0, 0, 1, 0, 1)};
	g->map = color_map(2, v3v, c3);
	check_color(eval(g, 0.4, 0, 0), 0.5000000596, 0, 0.4999999404, 0.2500000298, 0.5999999642);
	pigment_unref(g);
}

static struct pigment *solid(double r, double g, double b)
{
	struct pigment *p = pigment_new();
	p->color = col(r, g, b, 0, 0);
	return p;
}

static void test_pigment_map_and_average(void **state)
{
	(void)state;
	/* gradient x pigment_map { [0 red][1 checker] } */
	struct pigment *g = pattern_pigment(PAT_GRADIENT);
	g->pat.vec = v3(1, 0, 0);
	g->map = blend_map_new(MAP_PIGMENT, 2);
	g->map->e[0].value = 0;
	g->map->e[0].item = solid(1, 0, 0);
	g->map->e[1].value = 1;
	g->map->e[1].item = pattern_pigment(PAT_CHECKER);
	/* at x = 0.25 (checker there is blue): 0.75 red + 0.25 blue */
	check_color(eval(g, 0.25, 0.5, 0.5), 0.75, 0, 0.25, 0, 0);
	pigment_unref(g);

	/* average pigment_map { [1 red][3 green] } */
	struct pigment *a = pattern_pigment(PAT_AVERAGE);
	a->map = blend_map_new(MAP_PIGMENT, 2);
	a->map->e[0].value = 1;
	a->map->e[0].item = solid(1, 0, 0);
	a->map->e[1].value = 3;
	a->map->e[1].item = solid(0, 1, 0);
	check_color(eval(a, 0, 0, 0), 0.25, 0.75, 0, 0, 0);
	pigment_unref(a);

	/* a block pattern takes its list by index: checker red, blue */
	struct pigment *c = pattern_pigment(PAT_CHECKER);
	c->map = color_map(2, (const double[]){0, 1}, (const struct rgbft[]){col(1, 0, 0, 0, 0), col(0, 0, 1, 0, 0)});
	check_color(eval(c, 0.5, 0.5, 0.5), 1, 0, 0, 0, 0);
	check_color(eval(c, 1.5, 0.5, 0.5), 0, 0, 1, 0, 0);
	pigment_unref(c);
}

static void test_normals(void **state)
{
	(void)state;
	struct pattern_ctx ctx = ctx_at(0.3, 0, 0.2);
	vec3 n = v3(0, 1, 0);
	/* no pattern: unchanged */
	struct normal *none = normal_new(PAT_NONE);
	vec3 r = normal_eval(none, n, &ctx);
	assert_true(r.x == 0 && r.y == 1 && r.z == 0);
	normal_unref(none);
	/* gradient x rises along +x: the normal leans towards -x, more with
	 * a larger bump size, and stays unit */
	struct normal *gx = normal_new(PAT_GRADIENT);
	gx->pat.vec = v3(1, 0, 0);
	gx->amount = 0.5;
	vec3 a = normal_eval(gx, n, &ctx);
	assert_true(a.x < 0 && fabs(a.z) < 1e-9);
	assert_true(fabs(v3_len(a) - 1) < 1e-12);
	gx->amount = 1.0;
	vec3 b = normal_eval(gx, n, &ctx);
	assert_true(b.x < a.x);
	normal_unref(gx);
	/* a normal_map blends the entries' normals */
	struct normal *nm = normal_new(PAT_GRADIENT);
	nm->pat.vec = v3(1, 0, 0);
	nm->map = blend_map_new(MAP_NORMAL, 2);
	nm->map->e[0].value = 0;
	nm->map->e[0].item = normal_new(PAT_NONE);
	nm->map->e[1].value = 1;
	struct normal *gz = normal_new(PAT_GRADIENT);
	gz->pat.vec = v3(0, 0, 1);
	nm->map->e[1].item = gz;
	vec3 c = normal_eval(nm, n, &ctx);
	assert_true(c.z < 0 && c.z > normal_eval(gz, n, &ctx).z);
	normal_unref(nm);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_default_maps),
		cmocka_unit_test(test_block_defaults),
		cmocka_unit_test(test_color_map_lookup),
		cmocka_unit_test(test_pigment_map_and_average),
		cmocka_unit_test(test_normals),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

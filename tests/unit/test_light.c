/* test_light.c: lights from the parser to the tracer (light_parse.c,
 * render/light.c, prepare_features): the effects a scene calls for, the
 * light at a point (spotlight and cylinder cones, fading) and the weights
 * of area-light samples. The expected values are POV-Ray 3.7's, measured
 * by rendering a white diffuse plane (ambient 0, diffuse 1, assumed_gamma
 * 1) with an orthographic camera to 16-bit linear PPM and dividing each
 * pixel by the cosine of incidence; the area-light weights are the steps
 * of the light fraction as a half-plane occluder uncovers one sample after
 * another (a 1-D light: area_light <4,0,0>, <0,1,0>, N, 1). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "lang/diag.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "render/light.h"
#include "render/prepare.h"
#include "scene/object.h"
#include "scene/scene.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "testutil.h"
#include "parsetext.h"


static unsigned features_of(const char *text)
{
	struct parsed r;
	parse_text(&r, text);
	unsigned f = prepare_features(r.s);
	parsed_free(&r);
	return f;
}

#define LIGHT_BITS (FEAT_SHADOWS | FEAT_AREA_LIGHTS | FEAT_SPOTLIGHTS | FEAT_LIGHT_FADE | FEAT_PHONG)

/* Which light effects tiny scenes call for. */
static void test_features(void **state)
{
	(void)state;
	const char *obj = "sphere { 0, 1 finish { phong 1 } }\n";
	char buf[512];
	struct {
		const char *light;
		unsigned want;
	} cases[] = {
		{"light_source { <0,5,0>, rgb 1 }", FEAT_SHADOWS | FEAT_PHONG},
		/* shadowless: no shadows and no highlights */
		{"light_source { <0,5,0>, rgb 1 shadowless }", 0},
		{"light_source { <0,5,0>, rgb 1 area_light x, z, 3, 3 }", FEAT_SHADOWS | FEAT_AREA_LIGHTS | FEAT_PHONG},
		/* a 1x1 area light is a point light; a shadowless one casts no soft shadows */
		{"light_source { <0,5,0>, rgb 1 area_light x, z, 1, 1 }", FEAT_SHADOWS | FEAT_PHONG},
		{"light_source { <0,5,0>, rgb 1 area_light x, z, 3, 3 shadowless }", 0},
		/* area_illumination shades from the grid even without shadows */
		{"light_source { <0,5,0>, rgb 1 area_light x, z, 3, 3 shadowless area_illumination }", FEAT_AREA_LIGHTS},
		{"light_source { <0,5,0>, rgb 1 area_light x, z, 3, 3 shadowless area_illumination off }", 0},
		{"light_source { <0,5,0>, rgb 1 spotlight point_at 0 }", FEAT_SHADOWS | FEAT_SPOTLIGHTS | FEAT_PHONG},
		{"light_source { <0,5,0>, rgb 1 cylinder point_at 0 }", FEAT_SHADOWS | FEAT_SPOTLIGHTS | FEAT_PHONG},
		{"light_source { <0,5,0>, rgb 1 parallel point_at 0 }", FEAT_SHADOWS | FEAT_PHONG},
		{"light_source { <0,5,0>, rgb 1 fade_distance 2 fade_power 2 }", FEAT_SHADOWS | FEAT_LIGHT_FADE | FEAT_PHONG},
		/* fading needs both */
		{"light_source { <0,5,0>, rgb 1 fade_power 2 }", FEAT_SHADOWS | FEAT_PHONG},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		snprintf(buf, sizeof buf, "#version 3.7;\n%s%s\n", obj, cases[i].light);
		unsigned got = features_of(buf) & LIGHT_BITS;
		if (got != cases[i].want)
			fail_msg("%s: features %#x, want %#x", cases[i].light, got, cases[i].want);
	}
	/* An area light over a scene where nothing casts shadows. */
	unsigned f = features_of("#version 3.7;\nsphere { 0, 1 no_shadow }\n"
	                         "light_source { <0,5,0>, rgb 1 area_light x, z, 3, 3 }\n");
	assert_int_equal(f & (FEAT_SHADOWS | FEAT_AREA_LIGHTS), 0);
}

/* Rays track the interiors they cross (for no fog inside solid objects)
 * only when there is fog or a rainbow and something see-through. */
static void test_fog_interiors_feature(void **state)
{
	(void)state;
	const char *clear = "sphere { 0, 1 pigment { rgbf <1, 1, 1, 0.9> } }\n";
	const char *opaque = "sphere { 0, 1 pigment { rgb 1 } }\n";
	const char *fog = "fog { distance 3 color rgb 1 }\n";
	const char *rainbow = "rainbow { angle 42 width 5 distance 1e3 direction z "
	                      "color_map { [0 rgbt <1,0,0,0.5>] [1 rgbt <0,0,1,0.5>] } }\n";
	struct {
		const char *a, *b;
		bool want;
	} cases[] = {
		{clear, fog, true}, {clear, rainbow, true}, {opaque, fog, false}, {clear, "", false},
	};
	char buf[512];
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		snprintf(buf, sizeof buf, "#version 3.7;\n%s%s", cases[i].a, cases[i].b);
		bool got = (features_of(buf) & FEAT_INTERIORS) != 0;
		if (got != cases[i].want)
			fail_msg("%s%s: interiors %d, want %d", cases[i].a, cases[i].b, got, cases[i].want);
	}
}

/* The light set of a parsed scene, prepared. */
struct lit_scene {
	struct parsed r;
	struct prepared *p;
	struct light_set *ls;
};

static void lit_open(struct lit_scene *t, const char *text)
{
	parse_text(&t->r, text);
	t->p = prepare_scene(t->r.s);
	t->ls = light_set_new(t->p);
}

static void lit_close(struct lit_scene *t)
{
	light_set_free(t->ls);
	prepared_free(t->p);
	parsed_free(&t->r);
}

/* The light on the plane z = 0 at (x, 0, 0), over the cosine of incidence
 * for lights that shine from a point. */
static double atten_at(const struct light_rt *L, double x)
{
	struct light_ray lr;
	if (!light_at(L, v3(x, 0, 0), &lr))
		return 0;
	return lr.atten;
}

static void test_spotlight(void **state)
{
	(void)state;
	struct lit_scene t;
	lit_open(&t, "#version 3.7;\nplane { z, 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 spotlight radius 20 falloff 40 point_at 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 spotlight radius 20 falloff 40 tightness 5 point_at 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 spotlight point_at 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 spotlight radius 40 falloff 20 point_at 0 }\n");
	/* (angle, measured) pairs: x = tan(angle). */
	double a = tan(29.127 * M_PI / 180), b = tan(25.530 * M_PI / 180), c = tan(38.520 * M_PI / 180);
	assert_float_equal(atten_at(&t.ls->v[0], 0), 1.0, 1e-4);
	assert_float_equal(atten_at(&t.ls->v[0], a), 0.67521, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[0], b), 0.88122, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[0], c), 0.02491, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[0], tan(41.2 * M_PI / 180)), 0, 1e-9);
	assert_float_equal(atten_at(&t.ls->v[1], tan(13.431 * M_PI / 180)), 0.87053, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[1], a), 0.34344, 2e-4);
	/* defaults 30 and 45 */
	assert_float_equal(atten_at(&t.ls->v[2], tan(29.127 * M_PI / 180)), 1.0, 1e-4);
	assert_float_equal(atten_at(&t.ls->v[2], tan(38.520 * M_PI / 180)), 0.46057, 2e-4);
	/* a falloff below the radius: a hard edge at the radius */
	assert_float_equal(atten_at(&t.ls->v[3], tan(39.890 * M_PI / 180)), 1.0, 1e-9);
	assert_float_equal(atten_at(&t.ls->v[3], tan(43.688 * M_PI / 180)), 0, 1e-9);
	lit_close(&t);
}

static void test_cylinder_and_fade(void **state)
{
	(void)state;
	struct lit_scene t;
	lit_open(&t, "#version 3.7;\nplane { z, 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 cylinder radius 0.5 falloff 1.5 point_at 0 }\n"
	             "light_source { <0,0,-1>, rgb 1 cylinder radius 0.5 falloff 1.5 tightness 3 point_at 0 }\n"
	             "light_source { <0,0,-2>, rgb 1 fade_distance 1 fade_power 2 }\n"
	             "light_source { <0,0,1>, rgb 1 cylinder radius 1 falloff 2 point_at <0,0,2> }\n");
	/* A cylinder light shines along its axis: no cosine to take out. */
	struct light_ray lr;
	assert_true(light_at(&t.ls->v[0], v3(0.3, 0, 0), &lr));
	assert_float_equal(lr.dir.z, -1, 1e-12);
	assert_float_equal(atten_at(&t.ls->v[0], 0.3980), 1.0, 1e-9);
	assert_float_equal(atten_at(&t.ls->v[0], 0.5572), 0.99063, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[0], 0.9552), 0.56698, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[1], 0.0796), 0.84908, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[1], 0.3980), 0.39653, 2e-4);
	assert_float_equal(atten_at(&t.ls->v[1], 0.7960), 0.08155, 2e-4);
	/* fade: 2 / (1 + (d / fade_distance)^fade_power); at d = 2: 0.4 */
	assert_float_equal(atten_at(&t.ls->v[2], 0), 0.4, 1e-12);
	/* behind a cylinder light: no light */
	assert_false(light_at(&t.ls->v[3], v3(0, 0, 0), &lr));
	lit_close(&t);
}

/* Fading of parallel lights: by the signed distance to the light's plane
 * (POV-Ray 3.7, a white plane y = 0 under a parallel light with
 * fade_distance 1: constant over the plane, 0.66667 at height 2 with power
 * 1, 0.4 with power 2, and no light 3 units behind the plane). */
static void test_parallel_fade(void **state)
{
	(void)state;
	struct lit_scene t;
	lit_open(&t, "#version 3.7;\nplane { y, 0 }\n"
	             "light_source { <1,2,0>, rgb 1 parallel point_at <1,1,0> fade_distance 1 fade_power 1 }\n"
	             "light_source { <1,2,0>, rgb 1 parallel point_at <1,1,0> fade_distance 1 fade_power 2 }\n"
	             "light_source { <1,-3,0>, rgb 1 parallel point_at <1,-4,0> fade_distance 1 fade_power 1 }\n"
	             "light_source { <1,2,0>, rgb 1 cylinder radius 9 falloff 10 point_at <1,1,0> "
	             "fade_distance 1 fade_power 1 }\n");
	struct light_ray lr;
	for (double x = -3; x <= 3; x += 1.5) {
		assert_true(light_at(&t.ls->v[0], v3(x, 0, 0.5), &lr));
		assert_float_equal(lr.atten, 2.0 / 3, 1e-12);
		assert_true(light_at(&t.ls->v[1], v3(x, 0, 0.5), &lr));
		assert_float_equal(lr.atten, 0.4, 1e-12);
		assert_false(light_at(&t.ls->v[2], v3(x, 0, 0.5), &lr));
		assert_true(light_at(&t.ls->v[3], v3(x, 0, 0.5), &lr));
		assert_float_equal(lr.atten, 2.0 / 3, 1e-12);
	}
	lit_close(&t);
}

/* area_illumination: the light on a white diffuse plane y = 0 under a
 * 5 x 1 area light at height 1 is the mean over its points of each one's
 * cosine times its cone and fading. POV-Ray 3.7's values (16-bit linear
 * PNG, File_Gamma 1) at x = 0.25, 1.25, 2.25, 2.75; the second light is
 * an area spotlight (radius 20, falloff 40, point_at the origin: its cone
 * moves with each point), the third fades (distance 1, power 2). */
static void test_area_illumination(void **state)
{
	(void)state;
	struct lit_scene t;
	lit_open(&t, "#version 3.7;\nplane { y, 0 }\n"
	             "light_source { <0,1,0>, rgb 1 area_light <4,0,0>, <0,0,1>, 5, 1 area_illumination }\n"
	             "light_source { <0,1,0>, rgb 1 area_light <4,0,0>, <0,0,1>, 5, 1 area_illumination "
	             "spotlight radius 20 falloff 40 point_at <0,0,0> }\n"
	             "light_source { <0,1,0>, rgb 1 area_light <4,0,0>, <0,0,1>, 5, 1 area_illumination "
	             "fade_distance 1 fade_power 2 }\n");
	static const double xs[4] = {0.25, 1.25, 2.25, 2.75};
	static const double want[3][4] = {
		{0.659419, 0.619013, 0.504814, 0.42031},
		{0.209995, 0.209995, 0.194034, 0.015961},
		{0.445365, 0.415534, 0.295216, 0.188144},
	};
	struct light_point pts[5];
	for (int l = 0; l < 3; l++) {
		const struct light_rt *L = &t.ls->v[l];
		assert_true(L->illum);
		for (int i = 0; i < 4; i++) {
			assert_true(light_area_points(L, v3(xs[i], 0, 0), pts));
			double sum = 0;
			for (int k = 0; k < 5; k++)
				sum += pts[k].atten * fmax(0, pts[k].dir.y);
			assert_float_equal(sum / 5, want[l][i], 2e-5);
		}
	}
	lit_close(&t);
}

/* Area weights: the test callback gives 1 for the samples in `on`. */
struct pick {
	const bool *on;
	const struct light_rt *L;
};

static rgb pick_test(void *ctx, vec3 target, int column)
{
	(void)column;
	const struct pick *k = ctx;
	/* The sample's index along axis1 (x from -2 to 2) from its position. */
	int n = k->L->n1;
	int i = (int)lround((target.x + 2) / 4 * (n - 1));
	double v = k->on[i] ? 1 : 0;
	return rgb_make(v, v, v);
}

/* The light fraction of a 1-D area light of n samples along x with the
 * samples in `on` visible (adaptive level `adaptive`, -1: none). */
static double area_fraction(int n, int adaptive, const bool *on)
{
	struct light_rt L = {0};
	L.pos = v3(0, 0, -2);
	L.area = true;
	L.n1 = n;
	L.n2 = 1;
	L.adaptive = adaptive;
	L.axis1 = v3(4, 0, 0);
	L.axis2 = v3(0, 1, 0);
	struct area_scratch sc;
	area_scratch_init(&sc, (size_t)n);
	struct pick k = {on, &L};
	rgb c = light_area(&L, v3(0, 0, 0), &sc, pick_test, &k);
	area_scratch_free(&sc);
	return c.r;
}

static void test_area_weights(void **state)
{
	(void)state;
	/* POV-Ray's weights of each sample (every sample tested). */
	static const double w4[] = {0.25, 0.25, 0.25, 0.25};
	static const double w5[] = {0.125, 0.25, 0.25, 0.25, 0.125};
	static const double w6[] = {0.125, 0.25, 0.125, 0.125, 0.25, 0.125};
	static const double w7[] = {0.125, 0.125, 0.125, 0.25, 0.125, 0.125, 0.125};
	static const double w9[] = {0.0625, 0.125, 0.125, 0.125, 0.125, 0.125, 0.125, 0.125, 0.0625};
	const double *ws[] = {w4, w5, w6, w7, w9};
	int ns[] = {4, 5, 6, 7, 9};
	for (int c = 0; c < 5; c++) {
		for (int i = 0; i < ns[c]; i++) {
			bool on[9] = {false};
			on[i] = true;
			assert_float_equal(area_fraction(ns[c], -1, on), ws[c][i], 1e-12);
		}
	}
	/* A bar hiding the three middle samples of 9: adaptive 0 sees only
	 * the corners (all light); adaptive 1 also tests the middle one, finds
	 * a difference and samples everything (1 - 3/8). */
	bool bar[9] = {true, true, true, false, false, false, true, true, true};
	assert_float_equal(area_fraction(9, 0, bar), 1.0, 1e-12);
	assert_float_equal(area_fraction(9, 1, bar), 0.625, 1e-12);
	assert_float_equal(area_fraction(9, -1, bar), 0.625, 1e-12);
}

/* Parsing: transformations move what the light has so far; identifiers;
 * looks_like placed at the light; light groups. */
static void test_parse(void **state)
{
	(void)state;
	struct parsed r;
	parse_text(&r, "#version 3.7;\n"
	               "#declare L = light_source { <1,2,3>, rgb <1,0.5,0.25> spotlight translate x point_at <0,0,0> }\n"
	               "light_source { L translate y }\n"
	               "light_source { 0, rgb 1 looks_like { sphere { <0,1,0>, 0.5 } } translate <0,2,0> }\n"
	               "light_group { sphere { 0, 1 } light_source { 5, rgb 1 } global_lights on }\n");
	assert_int_equal(r.s->nlights, 3);
	const struct light *l = &r.s->lights[0];
	assert_int_equal(l->kind, LIGHT_SPOT);
	assert_float_equal(l->pos.x, 2, 1e-12);
	assert_float_equal(l->pos.y, 3, 1e-12);
	/* point_at given after `translate x`, then moved by `translate y` */
	assert_float_equal(l->point_at.x, 0, 1e-12);
	assert_float_equal(l->point_at.y, 1, 1e-12);
	assert_float_equal(l->radius, 30, 0);
	assert_float_equal(l->falloff, 45, 0);
	assert_float_equal(l->color.g, 0.5, 0);
	/* the looks_like sphere went into the scene, at the light, without shadow */
	assert_int_equal(r.s->nobjects, 2);
	const struct object *o = r.s->objects[0];
	assert_true(o->flags & OBJ_NO_SHADOW);
	struct aabb b = object_world_bounds(o);
	assert_float_equal((b.lo.y + b.hi.y) / 2, 3, 1e-9);
	/* the group: its light and its sphere share a group that takes global lights */
	const struct light *g = &r.s->lights[2];
	assert_int_not_equal(g->group, 0);
	assert_true(r.s->groups[g->group].global_lights);
	struct object **kids;
	const struct object *u = r.s->objects[1];
	assert_int_equal(u->ops->children((struct object *)u, &kids), 1);
	assert_int_equal(kids[0]->light_group, g->group);
	parsed_free(&r);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_features),
		cmocka_unit_test(test_fog_interiors_feature),
		cmocka_unit_test(test_spotlight),
		cmocka_unit_test(test_cylinder_and_fade),
		cmocka_unit_test(test_parallel_fade),
		cmocka_unit_test(test_area_illumination),
		cmocka_unit_test(test_area_weights),
		cmocka_unit_test(test_parse),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_texture_parse.c: what the material parser builds (texture_parse.c):
 * transformations reaching only the textures given before them, layered
 * textures, block lists completed with POV-Ray's defaults, the old colour
 * map entry form, CSG textures and interiors passed to children, and
 * pattern parameters. The scene rules checked are POV-Ray's: a texture
 * given before a transformation moves with the object and one given after
 * does not (measured: a checker pigment before/after `scale 2` renders
 * with 2-unit or 1-unit squares); several texture statements on one
 * object layer (measured: `object { O texture { rgbt <0,0,1,0.5> } }`
 * over a red O renders magenta, (188, 0, 188) in a 40x20 render); the
 * default colours of block lists were measured with function { pigment {
 * } } (checker: blue, green; hexagon: blue, green, red; brick: grey 0.5
 * mortar, <0.6, 0.15, 0.15> brick). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "lang/diag.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "scene/object.h"
#include "scene/scene.h"
#include "scene/texture.h"

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "testutil.h"
#include "parsetext.h"


/* The first op of a pattern as a transformation's x scale. */
static double op_scale_x(const struct pattern *pt)
{
	assert_true(pt->nops >= 1);
	assert_int_equal(pt->ops[0].kind, POP_TRANSFORM);
	return pt->ops[0].xf.fwd.m[0][0];
}

static void test_transform_order(void **state)
{
	(void)state;
	struct parsed r;
	parse_text(&r, "#version 3.7;\n"
	               "sphere { 0, 1 pigment { checker } scale 2 }\n"
	               "sphere { 0, 1 scale 2 pigment { checker } }\n"
	               "sphere { 0, 1 pigment { checker scale 3 } scale 2 }\n");
	assert_int_equal(r.s->nobjects, 3);
	struct texture *t0 = r.s->objects[0]->tex, *t1 = r.s->objects[1]->tex, *t2 = r.s->objects[2]->tex;
	assert_int_equal(t0->pigment->pat.kind, PAT_CHECKER);
	assert_near(op_scale_x(&t0->pigment->pat), 2, 1e-12);
	assert_int_equal(t1->pigment->pat.nops, 0);
	assert_near(op_scale_x(&t2->pigment->pat), 6, 1e-12);
	parsed_free(&r);
}

/* uv_mapping in a pigment, normal or texture block, with POV-Ray's rules
 * (measured by rendering a uv-checkered sphere at 160x120, each variant
 * compared with `texture { uv_mapping pigment { ... } }`): the flag is set
 * before or after the block's identifier and survives the pattern type
 * read after it; a pattern type after a uv-mapped identifier starts a new,
 * world-mapped pattern; transformations in the block before its end move
 * the pattern (`uv_mapping P scale 2` renders 2x squares) and later ones
 * do not (`pigment { Q scale 2 }`, `texture { T scale 2 }` and the
 * object's `rotate` render as Q alone). */
static void test_uv_mapping(void **state)
{
	(void)state;
	struct parsed r;
	parse_text(&r, "#version 3.7;\n"
	               "#declare P = pigment { checker scale 0.5 }\n"
	               "#declare Q = pigment { uv_mapping checker scale 0.5 }\n"
	               "sphere { 0, 1 pigment { uv_mapping checker scale 0.5 } }\n"
	               "sphere { 0, 1 pigment { uv_mapping P scale 2 } }\n"
	               "sphere { 0, 1 pigment { Q scale 2 } rotate y*30 }\n"
	               "sphere { 0, 1 pigment { Q bozo } }\n"
	               "sphere { 0, 1 normal { uv_mapping bumps 0.5 } }\n"
	               "sphere { 0, 1 texture { uv_mapping pigment { P } } scale 3 }\n");
	assert_int_equal(r.s->nobjects, 6);
	const struct pattern *p0 = &r.s->objects[0]->tex->pigment->pat;
	assert_int_equal(p0->kind, PAT_CHECKER);
	assert_true(p0->uv_mapping);
	assert_near(op_scale_x(p0), 0.5, 1e-12);
	const struct pattern *p1 = &r.s->objects[1]->tex->pigment->pat;
	assert_true(p1->uv_mapping);
	assert_near(op_scale_x(p1), 1, 1e-12);
	const struct pattern *p2 = &r.s->objects[2]->tex->pigment->pat;
	assert_true(p2->uv_mapping);
	assert_int_equal(p2->nops, 1);
	assert_near(op_scale_x(p2), 0.5, 1e-12);
	const struct pattern *p3 = &r.s->objects[3]->tex->pigment->pat;
	assert_int_equal(p3->kind, PAT_BOZO);
	assert_false(p3->uv_mapping);
	assert_true(r.s->objects[4]->tex->normal->pat.uv_mapping);
	const struct pattern *p5 = &r.s->objects[5]->tex->pigment->pat;
	assert_true(p5->uv_mapping);
	assert_near(op_scale_x(p5), 0.5, 1e-12);
	parsed_free(&r);
}

static void test_layers_and_lists(void **state)
{
	(void)state;
	struct parsed r;
	parse_text(&r, "#version 3.7;\n"
	               "#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }\n"
	               "sphere { 0, 1 texture { L } texture { pigment { rgbt <0, 0, 1, 0.5> } } }\n"
	               "sphere { 0, 1 pigment { hexagon color rgb 0.1 } }\n"
	               "sphere { 0, 1 pigment { brick color rgb 1 } }\n"
	               "sphere { 0, 1 pigment { gradient x color_map { [0.2 0.6 color rgb 0 color rgb 1] [1 rgb 0.5] } } }\n");
	assert_int_equal(r.s->nobjects, 4);
	/* top layer first: blue over L's red over L's white */
	struct texture *t = r.s->objects[0]->tex;
	assert_near(t->pigment->color.b, 1, 0);
	assert_non_null(t->next);
	assert_near(t->next->pigment->color.r, 1, 0);
	assert_near(t->next->pigment->color.t, 0.5, 0);
	assert_non_null(t->next->next);
	assert_near(t->next->next->pigment->color.g, 1, 0);
	assert_null(t->next->next->next);
	/* hexagon: the written entry, then POV-Ray's green and red */
	struct blend_map *m = r.s->objects[1]->tex->pigment->map;
	assert_int_equal(m->kind, MAP_COLOR);
	assert_int_equal(m->n, 3);
	assert_near(m->e[0].color.r, 0.1, 1e-15);
	assert_near(m->e[1].color.g, 1, 0);
	assert_near(m->e[2].color.r, 1, 0);
	assert_near(m->e[2].value, 2, 0);
	m = r.s->objects[2]->tex->pigment->map;
	assert_int_equal(m->n, 2);
	/* brick's default colour, single precision as POV-Ray keeps it
	 * (0.6000000238 printed; see test_texture_eval.c) */
	assert_near(m->e[1].color.r, (double)0.6f, 1e-15);
	assert_near(m->e[1].color.g, (double)0.15f, 1e-15);
	/* the old form is two entries */
	m = r.s->objects[3]->tex->pigment->map;
	assert_int_equal(m->n, 3);
	assert_near(m->e[0].value, 0.2, 1e-15);
	assert_near(m->e[1].value, 0.6, 1e-15);
	assert_near(m->e[1].color.g, 1, 0);
	assert_near(m->e[2].color.b, 0.5, 1e-15);
	parsed_free(&r);
}

/* The first leaf of a CSG (or the object itself). */
static struct object *first_leaf(struct object *o)
{
	struct object **kids;
	while (o->ops->children && o->ops->children(o, &kids) > 0)
		o = kids[0];
	return o;
}

static void test_csg_fill_and_params(void **state)
{
	(void)state;
	struct parsed r;
	parse_text(&r, "#version 3.7;\n"
	               "union { sphere { 0, 1 } sphere { x, 1 } pigment { rgb <0, 1, 0> } interior { ior 1.5 } }\n"
	               "sphere { 0, 1 pigment { crackle metric 1 offset 0.25 solid form <1, 0, 0> } }\n"
	               "sphere { 0, 1 normal { mandel 30, 0.3 exponent 3 exterior 2, 0.5 } }\n"
	               "sphere { 0, 1 pigment { bozo warp { black_hole <1, 2, 3>, 0.5 strength 2 } turbulence 0.5 octaves 3 } }\n");
	struct object *leaf = first_leaf(r.s->objects[0]);
	assert_non_null(leaf->tex);
	assert_near(leaf->tex->pigment->color.g, 1, 0);
	assert_non_null(leaf->interior);
	assert_near(leaf->interior->ior, 1.5, 0);
	const struct pattern *pt = &r.s->objects[1]->tex->pigment->pat;
	assert_int_equal(pt->kind, PAT_CRACKLE);
	assert_near(pt->f[0], 1, 0);
	assert_near(pt->f[1], 0.25, 0);
	assert_int_equal(pt->n[0], 1);
	assert_near(pt->form.x, 1, 0);
	const struct normal *n = r.s->objects[2]->tex->normal;
	assert_int_equal(n->pat.kind, PAT_MANDEL);
	assert_int_equal(n->pat.fractal.iterations, 30);
	assert_int_equal(n->pat.fractal.exponent, 3);
	assert_int_equal(n->pat.fractal.exterior_type, 2);
	assert_near(n->pat.fractal.exterior_factor, 0.5, 0);
	assert_near(n->amount, 0.3, 1e-15);
	pt = &r.s->objects[3]->tex->pigment->pat;
	assert_int_equal(pt->nops, 1);
	assert_int_equal(pt->ops[0].kind, POP_BLACK_HOLE);
	assert_near(pt->ops[0].v1.z, 3, 0);
	assert_near(pt->ops[0].f1, 0.5, 0);
	assert_near(pt->ops[0].f2, 2, 0); /* falloff's default */
	assert_near(pt->ops[0].f3, 2, 0);
	assert_true(pt->has_turbulence);
	assert_near(pt->turb.amount.y, 0.5, 0);
	assert_int_equal(pt->turb.octaves, 3);
	parsed_free(&r);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_transform_order),
		cmocka_unit_test(test_uv_mapping),
		cmocka_unit_test(test_layers_and_lists),
		cmocka_unit_test(test_csg_fill_and_params),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

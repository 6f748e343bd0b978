/* stmt.c: the scene statements: objects and their modifiers, textures,
 * lights, the camera, background and global settings. Each grammar
 * function names its production above it. */
#include "lang/parser.h"

#include "scene/fn.h"
#include "scene/camera.h"
#include "scene/light.h"

#include <stdlib.h>
#include <string.h>

void parse_free_texture_holder(void *h)
{
	texture_unref(*(struct texture **)h);
	free(h);
}

/* ---- lights (the camera is in camera_parse.c) ---- */

/* light_source := light_source '{' VECTOR [','] COLOR { light_item } '}' */
static void parse_light(struct parser *p, struct light *l)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	memset(l, 0, sizeof *l);
	l->kind = LIGHT_POINT;
	l->srcpos = at;
	l->pos = parse_vector(p);
	parse_accept(p, TOK_COMMA);
	struct rgbft c = parse_color(p);
	l->color = rgb_of(c);
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		if (parse_transform_item(p, &t)) {
			l->pos = mat_point(&t.fwd, l->pos);
			continue;
		}
		if (parse_accept_kw(p, KW_SHADOWLESS)) {
			l->shadowless = true;
			continue;
		}
		if (parse_accept_kw(p, KW_POINT_AT)) {
			(void)parse_vector(p); /* only spotlights use it */
			continue;
		}
		parse_expected(p, "a light_source item or '}'");
	}
}

/* ---- global settings, background ---- */

/* global_settings := global_settings '{' { setting } '}' */
static void parse_global_settings(struct parser *p)
{
	struct global_settings *gs = &p->scene->gs;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a global setting or '}'");
		switch (t->kw) {
		case KW_ASSUMED_GAMMA: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double g = parse_float(p);
			if (g <= 0)
				parse_error_at(p, at, "assumed_gamma must be greater than 0");
			gs->assumed_gamma = g;
			gs->assumed_gamma_set = true;
			break;
		}
		case KW_MAX_TRACE_LEVEL: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double m = parse_float(p);
			if (m < 1 || m > 256)
				parse_error_at(p, at, "max_trace_level must be between 1 and 256");
			gs->max_trace_level = (int)m;
			break;
		}
		case KW_ADC_BAILOUT: parse_advance(p); gs->adc_bailout = parse_float(p); break;
		case KW_AMBIENT_LIGHT: parse_advance(p); gs->ambient_light = rgb_of(parse_color(p)); break;
		case KW_IRID_WAVELENGTH: parse_advance(p); gs->irid_wavelength = rgb_of(parse_color(p)); break;
		case KW_NOISE_GENERATOR: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double g = parse_float(p);
			if (g != 1 && g != 2 && g != 3)
				parse_error_at(p, at, "noise_generator must be 1, 2 or 3, not %g", g);
			gs->noise_generator = (int)g;
			break;
		}
		case KW_NUMBER_OF_WAVES: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double n = parse_float(p);
			if (!(n >= 1 && n <= 1000))
				parse_error_at(p, at, "number_of_waves must be between 1 and 1000, not %g", n);
			gs->number_of_waves = (int)n;
			break;
		}
		case KW_CHARSET:
			parse_advance(p);
			if (parse_accept_kw(p, KW_ASCII))
				gs->charset = 0;
			else if (parse_accept_kw(p, KW_UTF8))
				gs->charset = 1;
			else if (parse_accept_kw(p, KW_SYS))
				gs->charset = 2;
			else
				parse_expected(p, "ascii, utf8 or sys");
			break;
		default:
			parse_expected(p, "a global setting or '}'");
		}
	}
}

/* background := background '{' COLOR '}' */
static void parse_background(struct parser *p)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	p->scene->background = parse_color(p);
	parse_expect(p, TOK_RBRACE);
}

/* ---- arrays ---- */

static void free_array_holder(void *h)
{
	val_clear(h);
	free(h);
}

/* One value for an array element or a declaration's right-hand side. */
struct value parse_rvalue(struct parser *p)
{
	struct value v;
	if (!parse_item_value(p, &v)) {
		if (!parse_starts_expression(p))
			parse_expected(p, "a value");
		v = parse_expression(p);
	}
	parse_take(p, &v);
	return v;
}

/* '{' item {',' item} '}' filling dimension d of a from element *next. */
static void parse_array_init(struct parser *p, struct array *a, int d, size_t *next)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_expect(p, TOK_LBRACE);
	int count = 0;
	for (;;) {
		if (count == a->dims[d])
			parse_error(p, "too many initialisers for dimension %d of the array (its size is %d)", d + 1, a->dims[d]);
		if (d + 1 < a->ndims) {
			parse_array_init(p, a, d + 1, next);
		} else {
			struct value v = parse_rvalue(p);
			a->elems[(*next)++] = v;
		}
		count++;
		if (parse_accept(p, TOK_COMMA)) {
			if (parse_is(p, TOK_RBRACE))
				break; /* a trailing comma */
			continue;
		}
		break;
	}
	parse_expect(p, TOK_RBRACE);
	if (count != a->dims[d])
		parse_error_at(p, at, "dimension %d of the array has size %d, but %d initialiser%s given", d + 1,
		               a->dims[d], count, count == 1 ? " was" : "s were");
}

/* array := array '[' INT ']' { '[' INT ']' } [ initialiser ] */
static struct array *parse_array(struct parser *p)
{
	parse_advance(p); /* array */
	int dims[ARRAY_MAX_DIMS], nd = 0;
	size_t total = 1;
	while (parse_is(p, TOK_LBRACKET)) {
		parse_advance(p);
		struct srcpos at = parse_peek(p)->pos;
		double n = parse_float(p);
		parse_expect(p, TOK_RBRACKET);
		if (nd == ARRAY_MAX_DIMS)
			parse_error_at(p, at, "an array has at most %d dimensions", ARRAY_MAX_DIMS);
		if (!(n >= 1) || n > 1e8)
			parse_error_at(p, at, "an array dimension must be from 1 to 100000000, not %g", n);
		dims[nd++] = (int)n;
		total *= (size_t)n;
		if (total > 100000000)
			parse_error_at(p, at, "the array would have more than 100000000 elements");
	}
	if (nd == 0)
		parse_expected(p, "'[' and the array's size");
	struct value *h = calloc(1, sizeof *h);
	if (!h) abort();
	h->kind = VAL_ARRAY;
	h->arr = array_new(nd, dims);
	int slot = parse_own(p, h, free_array_holder);
	if (parse_peek_cont(p)->kind == TOK_LBRACE) {
		size_t next = 0;
		parse_array_init(p, h->arr, 0, &next);
	}
	struct array *a = h->arr;
	parse_release(p, slot);
	free(h);
	return a;
}

/* ---- entry points ---- */

static void free_pigment_cb(void *x) { free(x); }

static void free_interior_holder(void *h)
{
	interior_unref(*(struct interior **)h);
	free(h);
}

static void free_material_cb(void *x)
{
	struct material *m = x;
	texture_unref(m->tex);
	interior_unref(m->interior);
	free(m);
}

static bool item_value(struct parser *p, struct value *out);

/* Inside a scene item's braces comparisons do not bind again until a new
 * parenthesis opens (see struct parser's rel_ok). */
bool parse_item_value(struct parser *p, struct value *out)
{
	bool rel = parse_set_rel(p, false);
	bool r = item_value(p, out);
	p->rel_ok = rel;
	return r;
}

static bool item_value(struct parser *p, struct value *out)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	struct srcpos at = t->pos;
	enum kw k = (enum kw)t->kw;
	memset(out, 0, sizeof *out);
	out->pos = at;
	if (parse_is_object_start(k)) {
		out->kind = VAL_OBJECT;
		out->obj = parse_object(p, false);
		return true;
	}
	switch (k) {
	case KW_ARRAY:
		out->kind = VAL_ARRAY;
		out->arr = parse_array(p);
		return true;
	case KW_TRANSFORM:
		out->kind = VAL_TRANSFORM;
		out->xf = parse_transform_value(p);
		return true;
	case KW_SPLINE:
		out->kind = VAL_SPLINE;
		out->spl = parse_spline(p);
		return true;
	case KW_FUNCTION:
		out->kind = VAL_FUNCTION;
		out->fn = parse_function(p);
		return true;
	case KW_PIGMENT:
		out->kind = VAL_PIGMENT;
		out->pig = parse_pigment_value(p);
		return true;
	case KW_FINISH: {
		struct finish *f = malloc(sizeof *f);
		if (!f) abort();
		*f = finish_default();
		int slot = parse_own(p, f, free_pigment_cb);
		parse_finish(p, f);
		parse_release(p, slot);
		out->kind = VAL_FINISH;
		out->fin = f;
		return true;
	}
	case KW_TEXTURE:
		out->kind = VAL_TEXTURE;
		out->tex = parse_texture_value(p);
		return true;
	case KW_NORMAL:
		out->kind = VAL_NORMAL;
		out->nrm = parse_normal_value(p);
		return true;
	case KW_INTERIOR: {
		struct interior **h = calloc(1, sizeof *h);
		if (!h) abort();
		int slot = parse_own(p, h, free_interior_holder);
		parse_interior(p, h);
		out->kind = VAL_INTERIOR;
		out->interior = *h;
		*h = NULL;
		parse_release(p, slot);
		free(h);
		return true;
	}
	case KW_MATERIAL: {
		struct material *m = calloc(1, sizeof *m);
		if (!m) abort();
		int slot = parse_own(p, m, free_material_cb);
		parse_material(p, m);
		parse_release(p, slot);
		out->kind = VAL_MATERIAL;
		out->mat = m;
		return true;
	}
	case KW_COLOR_MAP: case KW_COLOUR_MAP: case KW_PIGMENT_MAP: case KW_NORMAL_MAP: case KW_SLOPE_MAP:
	case KW_TEXTURE_MAP:
		out->kind = VAL_MAP;
		out->map = parse_map_value(p);
		return true;
	case KW_CAMERA: {
		struct camera *c = malloc(sizeof *c);
		if (!c) abort();
		*c = camera_default();
		int slot = parse_own(p, c, free_pigment_cb);
		parse_camera(p, c);
		parse_release(p, slot);
		out->kind = VAL_CAMERA;
		out->cam = c;
		return true;
	}
	case KW_LIGHT_SOURCE: {
		struct light *l = malloc(sizeof *l);
		if (!l) abort();
		int slot = parse_own(p, l, free_pigment_cb);
		parse_light(p, l);
		parse_release(p, slot);
		out->kind = VAL_LIGHT;
		out->light = l;
		return true;
	}
	default:
		return false;
	}
}

/* statement := object | light_source | camera | global_settings
 *            | background */
void parse_statement(struct parser *p)
{
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_KEYWORD) {
		enum kw k = (enum kw)t->kw;
		if (parse_is_object_start(k)) {
			struct object *o = parse_object(p, true);
			scene_add_object(p->scene, o);
			return;
		}
		switch (k) {
		case KW_LIGHT_SOURCE: {
			struct light l;
			parse_light(p, &l);
			scene_add_light(p->scene, &l);
			return;
		}
		case KW_CAMERA: {
			struct camera c = camera_default();
			parse_camera(p, &c);
			p->scene->camera = c;
			return;
		}
		case KW_GLOBAL_SETTINGS: parse_global_settings(p); return;
		case KW_BACKGROUND: parse_background(p); return;
		default: break;
		}
	}
	if (t->kind == TOK_IDENT && !parse_lookup(p, t->str))
		parse_undefined(p, t->str);
	parse_expected(p, "an object, light_source, camera, global_settings, background or directive");
}

/* stmt.c: the scene statements' dispatch (objects to objects.c, lights to
 * light_parse.c, the camera to camera_parse.c, background, fog, sky,
 * rainbow and global settings to atmos_parse.c), arrays and the values of
 * declarations. Each grammar function names its production above it. */
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
	/* Look for the next '[' without running a directive that may follow
	 * (`#declare A = array[3]` then `#declare A[0] = ...`). */
	while (parse_peek_cont(p)->kind == TOK_LBRACKET) {
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
		if (total > p->lim.array_size)
			parse_error_at(p, at, "the array would have more than %zu elements (lucent --limit array-size=N raises "
			               "the limit)", p->lim.array_size);
		if (!parse_memory_ok(total, sizeof(struct value)))
			parse_error_at(p, at, "the array's %zu elements would need more memory than the machine has", total);
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

static void free_camera_cb(void *x)
{
	camera_clear(x);
	free(x);
}

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
		int slot = parse_own(p, c, free_camera_cb);
		parse_camera(p, c);
		parse_release(p, slot);
		out->kind = VAL_CAMERA;
		out->cam = c;
		return true;
	}
	case KW_FOG: case KW_SKY_SPHERE: case KW_RAINBOW:
		return parse_atmos_value(p, out);
	case KW_LIGHT_SOURCE: {
		struct light *l = calloc(1, sizeof *l);
		if (!l) abort();
		int slot = parse_own(p, l, parse_free_light);
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
 *            | background | fog | sky_sphere | rainbow */
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
		case KW_LIGHT_SOURCE: parse_light_statement(p); return;
		case KW_CAMERA: {
			/* On the heap, so that a parse error frees what it holds. */
			struct camera *c = malloc(sizeof *c);
			if (!c) abort();
			*c = camera_default();
			int slot = parse_own(p, c, free_camera_cb);
			parse_camera(p, c);
			parse_release(p, slot);
			camera_clear(&p->scene->camera);
			p->scene->camera = *c;
			free(c);
			return;
		}
		default:
			if (parse_atmos_statement(p))
				return;
			break;
		}
	}
	if (t->kind == TOK_IDENT && !parse_lookup(p, t->str))
		parse_undefined(p, t->str);
	parse_expected(p, "an object, light_source, camera, global_settings, background or directive");
}

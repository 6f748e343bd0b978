/* atmos_parse.c: the statements about the scene as a whole: background,
 * fog, sky_sphere, rainbow and global_settings, as statements and as
 * #declare values. Each grammar function names its production above it;
 * defaults are in scene/atmos.c. */
#include "lang/parser.h"

#include "scene/atmos.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- shared ---- */

/* A float item's value that must be > lo (or >= lo when `or_equal`). */
static double parse_float_above(struct parser *p, const char *what, double lo, bool or_equal)
{
	struct srcpos at = parse_peek(p)->pos;
	double d = parse_float(p);
	if (!(d > lo || (or_equal && d == lo)))
		parse_error_at(p, at, "%s must be %s %g, not %g", what, or_equal ? "at least" : "greater than", lo, d);
	return d;
}

/* An identifier of kind `kind` right after a block's '{', or NULL (the
 * block starts with its items). A wrong kind is an error. */
static const struct value *leading_ident(struct parser *p, enum val_kind kind, const char *what)
{
	const struct value *v = parse_ident_value(p);
	if (!v || val_is_numeric(v))
		return NULL; /* a colour or a number: an item */
	if (v->kind != kind)
		parse_wrong_kind(p, v, what);
	parse_advance(p);
	return v;
}

/* Does the current token begin a colour (a colour keyword, rgb..., or an
 * expression such as a colour identifier)? */
static bool starts_color(struct parser *p)
{
	return parse_is_kw(p, KW_COLOR) || parse_is_kw(p, KW_COLOUR) || parse_starts_expression(p);
}

/* ---- fog ---- */

/* fog := fog '{' [FOG_IDENT] { fog_item } '}'
 * fog_item := fog_type INT | distance F | COLOR | turbulence V | turb_depth F
 *           | octaves N | omega F | lambda F | fog_offset F | fog_alt F
 *           | up V | transformation
 * A transformation turns `up` as it stands when the transformation is read
 * (an `up` after it is not turned); it moves nothing else, not even the
 * turbulence (measured on POV-Ray 3.7). */
static void parse_fog(struct parser *p, struct fog *f)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	*f = fog_default();
	const struct value *v = leading_ident(p, VAL_FOG, "a fog");
	if (v)
		*f = *v->fog;
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform step;
		if (parse_transform_item(p, &step)) {
			f->up = mat_dir(&step.fwd, f->up);
			continue;
		}
		const struct token *t = parse_peek(p);
		switch (t->kind == TOK_KEYWORD ? t->kw : KW_NONE) {
		case KW_FOG_TYPE: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double d = parse_float(p);
			if (d != 1 && d != 2)
				parse_error_at(p, at, "fog_type must be 1 (constant fog) or 2 (ground fog), not %g", d);
			f->type = (enum fog_type)(int)d;
			continue;
		}
		case KW_DISTANCE: parse_advance(p); f->distance = parse_float(p); continue;
		case KW_TURBULENCE:
			parse_advance(p);
			f->turb.amount = parse_vector(p);
			f->has_turbulence = true;
			continue;
		case KW_TURB_DEPTH: parse_advance(p); f->turb_depth = parse_float(p); continue;
		case KW_OCTAVES: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double d = parse_float(p);
			if (!(d >= 0 && d <= 1000))
				parse_error_at(p, at, "octaves must be from 0 to 1000, not %g", d);
			f->turb.octaves = (int)d;
			continue;
		}
		case KW_OMEGA: parse_advance(p); f->turb.omega = parse_float(p); continue;
		case KW_LAMBDA: parse_advance(p); f->turb.lambda = parse_float(p); continue;
		case KW_FOG_OFFSET: parse_advance(p); f->offset = parse_float(p); continue;
		case KW_FOG_ALT: parse_advance(p); f->alt = parse_float(p); continue;
		case KW_UP: parse_advance(p); f->up = parse_vector(p); continue;
		default: break;
		}
		if (!starts_color(p))
			parse_expected(p, "a fog item or '}'");
		f->color = parse_color(p);
	}
	/* A turbulence of <0,0,0> stirs nothing. */
	if (f->has_turbulence && f->turb.amount.x == 0 && f->turb.amount.y == 0 && f->turb.amount.z == 0)
		f->has_turbulence = false;
}

/* ---- sky_sphere ---- */

static void free_sky_holder(void *h)
{
	sky_sphere_free(*(struct sky_sphere **)h);
	free(h);
}

/* sky_sphere := sky_sphere '{' [SKY_SPHERE_IDENT] { sky_item } '}'
 * sky_item := pigment | emission COLOR | transformation
 * The transformations apply to the direction looked up, whatever their
 * place among the pigments (measured: POV-Ray gives the same image with a
 * rotation before or after the pigment). Returns the new sky (owned). */
static struct sky_sphere *parse_sky_sphere(struct parser *p)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct sky_sphere **h = calloc(1, sizeof *h);
	if (!h) abort();
	int slot = parse_own(p, h, free_sky_holder);
	const struct value *v = leading_ident(p, VAL_SKY_SPHERE, "a sky_sphere");
	*h = v ? sky_sphere_copy(v->sky) : sky_sphere_new();
	struct sky_sphere *s = *h;
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform step;
		if (parse_transform_item(p, &step)) {
			s->xf = xform_compose(&step, &s->xf);
			continue;
		}
		if (parse_is_kw(p, KW_PIGMENT)) {
			sky_sphere_add(s, parse_pigment_value(p));
			continue;
		}
		if (parse_accept_kw(p, KW_EMISSION)) {
			s->emission = rgb_of(parse_color(p));
			continue;
		}
		parse_expected(p, "pigment, emission, a transformation or '}'");
	}
	if (s->npigments == 0)
		parse_error_at(p, at, "a sky_sphere needs at least one pigment");
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return s;
}

/* ---- rainbow ---- */

static void free_rainbow_holder(void *h)
{
	rainbow_clear(h);
	free(h);
}

/* rainbow := rainbow '{' [RAINBOW_IDENT] { rainbow_item } '}'
 * rainbow_item := direction V | angle F | width F | distance F | jitter F
 *               | up V | arc_angle F | falloff_angle F | color_map
 * (no transformations: POV-Ray 3.7 refuses them too)
 * Into *out; the colour map's reference passes to it. */
static void parse_rainbow(struct parser *p, struct rainbow *out)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct rainbow *r = calloc(1, sizeof *r);
	if (!r) abort();
	int slot = parse_own(p, r, free_rainbow_holder);
	*r = rainbow_default();
	const struct value *v = leading_ident(p, VAL_RAINBOW, "a rainbow");
	if (v) {
		*r = *v->rainbow;
		if (r->color_map)
			blend_map_ref(r->color_map);
	}
	struct srcpos falloff_at = at;
	bool arc_given = false, falloff_given = false;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a rainbow item or '}'");
		switch (t->kw) {
		case KW_DIRECTION: parse_advance(p); r->direction = parse_vector(p); break;
		case KW_ANGLE: parse_advance(p); r->angle = parse_float(p); break;
		case KW_WIDTH: parse_advance(p); r->width = parse_float(p); break;
		case KW_DISTANCE: parse_advance(p); r->distance = parse_float(p); break;
		case KW_JITTER: parse_advance(p); r->jitter = parse_float(p); break;
		case KW_UP: parse_advance(p); r->up = parse_vector(p); break;
		case KW_ARC_ANGLE: {
			parse_advance(p);
			struct srcpos arc_at = parse_peek(p)->pos;
			arc_given = true;
			double d = parse_float(p);
			if (!(d >= 0 && d <= 360))
				parse_error_at(p, arc_at, "a rainbow's arc_angle must be from 0 to 360 degrees, not %g", d);
			r->arc_angle = d;
			break;
		}
		case KW_FALLOFF_ANGLE: {
			parse_advance(p);
			falloff_at = parse_peek(p)->pos;
			falloff_given = true;
			double d = parse_float(p);
			if (!(d >= 0 && d <= 360))
				parse_error_at(p, falloff_at, "a rainbow's falloff_angle must be from 0 to 360 degrees, not %g", d);
			r->falloff_angle = d;
			break;
		}
		case KW_COLOR_MAP: case KW_COLOUR_MAP: {
			struct blend_map *m = parse_map_value(p);
			if (r->color_map)
				blend_map_unref(r->color_map);
			r->color_map = m;
			break;
		}
		default: parse_expected(p, "a rainbow item or '}'");
		}
	}
	/* As in POV-Ray, the two angles are compared only when both are given. */
	if (arc_given && falloff_given && r->falloff_angle > r->arc_angle)
		parse_error_at(p, falloff_at, "a rainbow's falloff_angle (%g) must not be larger than its arc_angle (%g)",
		               r->falloff_angle, r->arc_angle);
	/* Without a falloff_angle of its own the arc ends sharply. */
	if (r->falloff_angle > r->arc_angle)
		r->falloff_angle = r->arc_angle;
	if (v3_dot(r->direction, r->direction) == 0)
		parse_error_at(p, at, "a rainbow needs a direction other than <0, 0, 0>");
	*out = *r;
	r->color_map = NULL;
	parse_release(p, slot);
	free(r);
}

/* ---- background, global_settings ---- */

/* background := background '{' COLOR '}'
 * As in POV-Ray 3.7, a background the scene gives is opaque unless its
 * colour says otherwise; the default (no statement) is transparent black. */
static void parse_background(struct parser *p)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	p->scene->background = parse_color(p);
	parse_expect(p, TOK_RBRACE);
}

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
		case KW_ASSUMED_GAMMA:
			parse_advance(p);
			gs->assumed_gamma = parse_float_above(p, "assumed_gamma", 0, false);
			gs->assumed_gamma_set = true;
			break;
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

/* ---- entry points ---- */

bool parse_atmos_statement(struct parser *p)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	struct atmosphere *a = &p->scene->atmos;
	switch (t->kw) {
	case KW_BACKGROUND: parse_background(p); return true;
	case KW_GLOBAL_SETTINGS: parse_global_settings(p); return true;
	case KW_FOG: {
		struct fog f;
		parse_fog(p, &f);
		atmos_add_fog(a, &f);
		return true;
	}
	case KW_SKY_SPHERE: {
		struct srcpos at = t->pos;
		struct sky_sphere *s = parse_sky_sphere(p);
		if (a->sky)
			parse_warning_at(p, at, "only one sky_sphere is used: this one replaces the one before");
		atmos_set_sky(a, s);
		return true;
	}
	case KW_RAINBOW: {
		struct rainbow r;
		parse_rainbow(p, &r);
		atmos_add_rainbow(a, &r);
		return true;
	}
	default: return false;
	}
}

bool parse_atmos_value(struct parser *p, struct value *out)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	switch (t->kw) {
	case KW_FOG: {
		struct fog *f = malloc(sizeof *f);
		if (!f) abort();
		int slot = parse_own(p, f, free);
		parse_fog(p, f);
		parse_release(p, slot);
		out->kind = VAL_FOG;
		out->fog = f;
		return true;
	}
	case KW_SKY_SPHERE:
		out->sky = parse_sky_sphere(p);
		out->kind = VAL_SKY_SPHERE;
		return true;
	case KW_RAINBOW: {
		struct rainbow *r = malloc(sizeof *r);
		if (!r) abort();
		int slot = parse_own(p, r, free);
		parse_rainbow(p, r);
		parse_release(p, slot);
		out->kind = VAL_RAINBOW;
		out->rainbow = r;
		return true;
	}
	default: return false;
	}
}

/* finish_parse.c: finish and interior statements. Each grammar function
 * names its production above it. */
#include "lang/parser.h"

#include <stdlib.h>
#include <string.h>

static rgb parse_rgb_or_float(struct parser *p)
{
	struct value e = parse_expression(p);
	if (e.kind == VAL_FLOAT)
		return rgb_make(e.v[0], e.v[0], e.v[0]);
	if (e.kind == VAL_VECTOR || e.kind == VAL_COLOR)
		return rgb_make(e.v[0], e.n > 1 ? e.v[1] : 0, e.n > 2 ? e.v[2] : 0);
	parse_error_at(p, e.pos, "expected a float or a color, found a %s", val_kind_name(e.kind));
}

/* finish := finish '{' [IDENT] { finish_item } '}' */
void parse_finish(struct parser *p, struct finish *f)
{
	parse_advance(p); /* finish */
	parse_expect(p, TOK_LBRACE);
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_FINISH)
			parse_wrong_kind(p, v, "a finish");
		*f = *v->fin;
		parse_advance(p);
	}
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a finish item or '}'");
		switch (t->kw) {
		case KW_AMBIENT: parse_advance(p); f->ambient = parse_rgb_or_float(p); break;
		case KW_EMISSION: parse_advance(p); f->emission = parse_rgb_or_float(p); break;
		case KW_DIFFUSE: parse_advance(p); f->diffuse = parse_float(p); break;
		case KW_BRILLIANCE: parse_advance(p); f->brilliance = parse_float(p); break;
		case KW_PHONG: parse_advance(p); f->phong = parse_float(p); break;
		case KW_PHONG_SIZE: parse_advance(p); f->phong_size = parse_float(p); break;
		case KW_SPECULAR: parse_advance(p); f->specular = parse_float(p); break;
		case KW_ROUGHNESS: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double r = parse_float(p);
			if (r <= 0)
				parse_error_at(p, at, "roughness must be greater than 0");
			f->roughness = r;
			break;
		}
		case KW_REFLECTION: parse_advance(p); f->reflection_min = f->reflection_max = parse_rgb_or_float(p); break;
		case KW_METALLIC:
			parse_advance(p);
			f->metallic = true;
			if (parse_starts_expression(p))
				f->metallic = parse_float(p) != 0;
			break;
		default:
			parse_expected(p, "a finish item or '}'");
		}
	}
}


/* interior := interior '{' [IDENT] { interior_item } '}'
 * interior_item := ior F | caustics F | dispersion F | dispersion_samples F
 *                | fade_distance F | fade_power F | fade_color COLOR
 * Replaces *in with the new interior (one reference). */
void parse_interior(struct parser *p, struct interior **in)
{
	parse_advance(p); /* interior */
	parse_expect(p, TOK_LBRACE);
	struct interior *n;
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_INTERIOR)
			parse_wrong_kind(p, v, "an interior");
		n = interior_copy(v->interior);
		parse_advance(p);
	} else {
		n = interior_new();
	}
	interior_unref(*in);
	*in = n;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "an interior item or '}'");
		switch (t->kw) {
		case KW_IOR: parse_advance(p); n->ior = parse_float(p); break;
		case KW_CAUSTICS: parse_advance(p); n->caustics = parse_float(p); break;
		case KW_DISPERSION: parse_advance(p); n->dispersion = parse_float(p); break;
		case KW_DISPERSION_SAMPLES: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double d = parse_float(p);
			if (d < 2)
				parse_error_at(p, at, "dispersion_samples must be at least 2");
			n->dispersion_samples = (int)d;
			break;
		}
		case KW_FADE_DISTANCE: parse_advance(p); n->fade_distance = parse_float(p); break;
		case KW_FADE_POWER: parse_advance(p); n->fade_power = parse_float(p); break;
		case KW_FADE_COLOR: case KW_FADE_COLOUR: parse_advance(p); n->fade_color = rgb_of(parse_color(p)); break;
		default:
			parse_expected(p, "an interior item or '}'");
		}
	}
}

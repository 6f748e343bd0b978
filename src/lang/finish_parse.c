/* finish_parse.c: finish and interior statements. Each grammar function
 * names its production above it. */
#include "lang/parser.h"

#include <math.h>
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

/* A float that must lie in [lo, hi] (hi = INFINITY: no upper bound);
 * `what` names it in the message. */
static double parse_float_in(struct parser *p, double lo, double hi, bool lo_open, const char *what)
{
	struct srcpos at = parse_peek(p)->pos;
	double v = parse_float(p);
	if (v < lo || (lo_open && v == lo) || v > hi) {
		if (hi == INFINITY)
			parse_error_at(p, at, "%s must be %s %g", what, lo_open ? "greater than" : "at least", lo);
		parse_error_at(p, at, "%s must be between %g and %g", what, lo, hi);
	}
	return v;
}

/* An optional boolean: absent means on. */
static bool parse_opt_bool(struct parser *p)
{
	return parse_starts_expression(p) ? parse_float(p) != 0 : true;
}

/* reflection_block := reflection '{' COLOR [',' COLOR] { reflection_item } '}'
 * reflection_item := fresnel [BOOL] | falloff F | exponent F | metallic [F] */
static void parse_reflection_block(struct parser *p, struct finish *f)
{
	parse_expect(p, TOK_LBRACE);
	rgb a = parse_rgb_or_float(p);
	f->reflection_min = f->reflection_max = a;
	if (parse_accept(p, TOK_COMMA))
		f->reflection_max = parse_rgb_or_float(p);
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a reflection item (fresnel, falloff, exponent, metallic) or '}'");
		switch (t->kw) {
		case KW_FRESNEL: parse_advance(p); f->reflection_fresnel = parse_opt_bool(p); break;
		case KW_FALLOFF: parse_advance(p); f->reflection_falloff = parse_float_in(p, 0, INFINITY, true, "falloff"); break;
		case KW_EXPONENT: parse_advance(p); f->reflection_exponent = parse_float_in(p, 0, INFINITY, true, "exponent"); break;
		case KW_METALLIC:
			parse_advance(p);
			f->reflection_metallic = parse_starts_expression(p) ? parse_float(p) : 1.0;
			break;
		default:
			parse_expected(p, "a reflection item (fresnel, falloff, exponent, metallic) or '}'");
		}
	}
}

/* irid_block := irid '{' F { thickness F | turbulence F } '}' */
static void parse_irid_block(struct parser *p, struct finish *f)
{
	parse_expect(p, TOK_LBRACE);
	f->irid = parse_float(p);
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "thickness, turbulence or '}'");
		switch (t->kw) {
		case KW_THICKNESS: parse_advance(p); f->irid_thickness = parse_float(p); break;
		case KW_TURBULENCE: parse_advance(p); f->irid_turbulence = parse_float(p); break;
		default:
			parse_expected(p, "thickness, turbulence or '}'");
		}
	}
}

/* finish := finish '{' [IDENT] { finish_item } '}'
 * finish_item := ambient COLOR | emission COLOR | diffuse [albedo] F [',' F]
 *              | brilliance F | crand F | phong [albedo] F | phong_size F
 *              | specular [albedo] F | roughness F | metallic [F]
 *              | reflection COLOR | reflection reflection_block
 *              | reflection_exponent F | conserve_energy [BOOL] | irid_block
 *              | subsurface '{' translucency COLOR '}'
 *              | ior F | caustics F | refraction F     (pre-3.1, with a warning)
 * `albedo` makes the amount the total reflectance: it is scaled, when the
 * block ends, by the factor for the brilliance, phong_size or roughness in
 * effect then (shade.c's shade_albedo_*). */
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
	bool alb_diffuse = false, alb_phong = false, alb_specular = false;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a finish item or '}'");
		struct srcpos at = t->pos;
		switch (t->kw) {
		case KW_AMBIENT: parse_advance(p); f->ambient = parse_rgb_or_float(p); break;
		case KW_EMISSION: parse_advance(p); f->emission = parse_rgb_or_float(p); break;
		case KW_DIFFUSE:
			parse_advance(p);
			alb_diffuse = parse_accept_kw(p, KW_ALBEDO);
			f->diffuse = parse_float(p);
			if (parse_accept(p, TOK_COMMA))
				f->diffuse_back = parse_float(p);
			break;
		case KW_BRILLIANCE: parse_advance(p); f->brilliance = parse_float(p); break;
		case KW_CRAND: parse_advance(p); f->crand = parse_float(p); break;
		case KW_PHONG:
			parse_advance(p);
			alb_phong = parse_accept_kw(p, KW_ALBEDO);
			f->phong = parse_float(p);
			break;
		case KW_PHONG_SIZE: parse_advance(p); f->phong_size = parse_float(p); break;
		case KW_SPECULAR:
			parse_advance(p);
			alb_specular = parse_accept_kw(p, KW_ALBEDO);
			f->specular = parse_float(p);
			break;
		case KW_ROUGHNESS: parse_advance(p); f->roughness = parse_float_in(p, 0, INFINITY, true, "roughness"); break;
		case KW_METALLIC:
			parse_advance(p);
			f->metallic = parse_starts_expression(p) ? parse_float(p) : 1.0;
			break;
		case KW_REFLECTION:
			parse_advance(p);
			if (parse_peek(p)->kind == TOK_LBRACE) {
				parse_reflection_block(p, f);
			} else {
				f->reflection_min = f->reflection_max = parse_rgb_or_float(p);
				f->reflection_fresnel = false;
			}
			break;
		case KW_REFLECTION_EXPONENT:
			parse_advance(p);
			f->reflection_exponent = parse_float_in(p, 0, INFINITY, true, "reflection_exponent");
			break;
		case KW_CONSERVE_ENERGY: parse_advance(p); f->conserve_energy = parse_opt_bool(p); break;
		case KW_IRID: parse_advance(p); parse_irid_block(p, f); break;
		case KW_SUBSURFACE:
			/* Subsurface light transport needs global_settings { subsurface },
			 * which lucent does not have; without it POV-Ray ignores this too. */
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			if (!parse_accept_kw(p, KW_TRANSLUCENCY))
				parse_expected(p, "translucency");
			parse_rgb_or_float(p);
			parse_expect(p, TOK_RBRACE);
			break;
		case KW_IOR:
			parse_advance(p);
			f->legacy_ior = parse_float_in(p, 0, INFINITY, true, "ior");
			parse_warning_at(p, at, "ior belongs in interior { }; moved into the object's interior");
			break;
		case KW_CAUSTICS:
			parse_advance(p);
			f->legacy_caustics = parse_float(p);
			parse_warning_at(p, at, "caustics belongs in interior { }; moved into the object's interior");
			break;
		case KW_REFRACTION:
			parse_advance(p);
			parse_float(p);
			parse_warning_at(p, at, "refraction is not needed to turn on refraction (ior does); ignored");
			break;
		default:
			parse_expected(p, "a finish item or '}'");
		}
	}
	if (alb_diffuse)
		f->diffuse *= (f->brilliance + 1) / 2;
	if (alb_phong)
		f->phong *= (f->phong_size + 1) / 2;
	if (alb_specular) {
		double n = 1 / f->roughness;
		f->specular *= (n + 2) / (4 * (2 - pow(2, -n / 2)));
	}
}


/* interior := interior '{' [IDENT] { interior_item } '}'
 * interior_item := ior F | caustics F | dispersion F | dispersion_samples F
 *                | fade_distance F | fade_power F | fade_color COLOR
 * Replaces *in with the new interior (one reference). Without an
 * identifier, the items change a copy of *in when there is one: as in
 * POV-Ray 3.7, a second interior block of an object adds to the first
 * (measured: `interior { ior 1.5 } interior { fade_distance 1 }` still
 * refracts). */
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
		n = *in ? interior_copy(*in) : interior_new();
	}
	interior_unref(*in);
	*in = n;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "an interior item or '}'");
		switch (t->kw) {
		case KW_IOR:
			parse_advance(p);
			n->ior = parse_float_in(p, 0, INFINITY, true, "ior");
			n->ior_given = true;
			break;
		case KW_CAUSTICS: parse_advance(p); n->caustics = parse_float(p); break;
		case KW_DISPERSION: parse_advance(p); n->dispersion = parse_float_in(p, 0, INFINITY, true, "dispersion"); break;
		case KW_DISPERSION_SAMPLES: {
			parse_advance(p);
			struct srcpos at = parse_peek(p)->pos;
			double d = parse_float(p);
			if (!(d >= 2))
				parse_error_at(p, at, "dispersion_samples must be at least 2");
			/* POV-Ray's int cast makes 3e9 negative: "minimum is 2" */
			if (d >= 2147483648.0)
				parse_error_at(p, at, "dispersion_samples must be from 2 to 2147483647, not %g", d);
			n->dispersion_samples = (int)d;
			break;
		}
		case KW_FADE_DISTANCE: parse_advance(p); n->fade_distance = parse_float_in(p, 0, INFINITY, false, "fade_distance"); break;
		case KW_FADE_POWER: parse_advance(p); n->fade_power = parse_float_in(p, 0, INFINITY, false, "fade_power"); break;
		case KW_FADE_COLOR: case KW_FADE_COLOUR: parse_advance(p); n->fade_color = rgb_of(parse_color(p)); break;
		default:
			parse_expected(p, "an interior item or '}'");
		}
	}
}

/* pattern_parse.c: the patterns of pigments, normals, textures and
 * pattern functions: the pattern keywords with their arguments, the
 * pattern modifiers (wave types, frequency and phase, turbulence, warps,
 * noise_generator, the kinds' own parameters) and function { pattern { } }'s
 * block. The lists and maps that go with a pattern are texture_parse.c's.
 * Each grammar function names its production above it. */
#include "lang/parser.h"

#include <string.h>

/* The block a pattern is read for, in messages. */
static const char *const use_names[] = {"pigment", "normal", "texture"};

/* The pattern a keyword names, or PAT_NONE. */
static enum pattern_kind pattern_of_kw(enum kw k)
{
	switch (k) {
	case KW_AGATE: return PAT_AGATE;
	case KW_AOI: return PAT_AOI;
	case KW_AVERAGE: return PAT_AVERAGE;
	case KW_BOXED: return PAT_BOXED;
	case KW_BOZO: return PAT_BOZO;
	case KW_BRICK: return PAT_BRICK;
	case KW_BUMPS: return PAT_BUMPS;
	case KW_CELLS: return PAT_CELLS;
	case KW_CHECKER: return PAT_CHECKER;
	case KW_CRACKLE: return PAT_CRACKLE;
	case KW_CUBIC: return PAT_CUBIC;
	case KW_CYLINDRICAL: return PAT_CYLINDRICAL;
	case KW_DENTS: return PAT_DENTS;
	case KW_FACETS: return PAT_FACETS;
	case KW_FUNCTION: return PAT_FUNCTION;
	case KW_GRADIENT: return PAT_GRADIENT;
	case KW_GRANITE: return PAT_GRANITE;
	case KW_HEXAGON: return PAT_HEXAGON;
	case KW_IMAGE_PATTERN: return PAT_IMAGE;
	case KW_JULIA: return PAT_JULIA;
	case KW_LEOPARD: return PAT_LEOPARD;
	case KW_MAGNET: return PAT_MAGNET;
	case KW_MANDEL: return PAT_MANDEL;
	case KW_MARBLE: return PAT_MARBLE;
	case KW_OBJECT: return PAT_OBJECT;
	case KW_ONION: return PAT_ONION;
	case KW_PAVEMENT: return PAT_PAVEMENT;
	case KW_PIGMENT_PATTERN: return PAT_PIGMENT;
	case KW_PLANAR: return PAT_PLANAR;
	case KW_QUILTED: return PAT_QUILTED;
	case KW_RADIAL: return PAT_RADIAL;
	case KW_RIPPLES: return PAT_RIPPLES;
	case KW_SLOPE: return PAT_SLOPE;
	case KW_SPHERICAL: return PAT_SPHERICAL;
	case KW_SPIRAL1: return PAT_SPIRAL1;
	case KW_SPIRAL2: return PAT_SPIRAL2;
	case KW_SPOTTED: return PAT_SPOTTED;
	case KW_SQUARE: return PAT_SQUARE;
	case KW_TILING: return PAT_TILING;
	case KW_TRIANGULAR: return PAT_TRIANGULAR;
	case KW_WAVES: return PAT_WAVES;
	case KW_WOOD: return PAT_WOOD;
	case KW_WRINKLES: return PAT_WRINKLES;
	default: return PAT_NONE;
	}
}

bool parse_at_pattern(struct parser *p, enum pattern_kind *k)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	*k = pattern_of_kw((enum kw)t->kw);
	return *k != PAT_NONE;
}

/* A pattern of kind k with POV-Ray's defaults for the kind's own
 * parameters (the manual's values). */
static struct pattern pattern_with_defaults(enum pattern_kind k)
{
	struct pattern pt = pattern_make(k);
	switch (k) {
	case PAT_AGATE: pt.f[0] = 1.0; break;                     /* agate_turb */
	case PAT_BRICK: pt.vec = v3(8, 3, 4.5); pt.vec2.x = 0.5; break;
	case PAT_CRACKLE: pt.f[0] = 2; pt.f[1] = 0; pt.form = v3(-1, 1, 0); break;
	case PAT_FACETS: pt.vec.x = 0.1; pt.f[0] = 2; break;       /* size; metric */
	case PAT_QUILTED: pt.f[0] = 1; pt.f[1] = 1; break;         /* control0, control1 */
	case PAT_GRADIENT: pt.vec = v3(1, 0, 0); break;
	case PAT_SLOPE: pt.f[0] = 0; pt.f[1] = 1; pt.f[2] = 0; pt.f[3] = 1; break;
	case PAT_PAVEMENT: pt.n[0] = 3; pt.n[1] = 1; pt.n[2] = 1; break;
	case PAT_JULIA: case PAT_MANDEL: case PAT_MAGNET:
		pt.fractal.exponent = 2;
		pt.fractal.magnet_type = 1;
		pt.fractal.exterior_type = 1;
		pt.fractal.interior_type = 0;
		pt.fractal.exterior_factor = pt.fractal.interior_factor = 1;
		break;
	/* The manual names the patterns whose wave is triangle_wave by default. */
	case PAT_MARBLE: case PAT_WOOD: case PAT_SPIRAL1: case PAT_SPIRAL2: pt.wave = WAVE_TRIANGLE; break;
	default: break;
	}
	return pt;
}

/* An integer parameter in [lo, hi], named `what` in the message. */
static int parse_int_in(struct parser *p, const char *what, int lo, int hi)
{
	struct srcpos at = parse_peek(p)->pos;
	double d = parse_float(p);
	if (!(d >= lo && d <= hi))
		parse_error_at(p, at, "%s must be from %d to %d, not %g", what, lo, hi, d);
	return (int)d;
}

static int parse_iterations(struct parser *p)
{
	struct srcpos at = parse_peek(p)->pos;
	double d = parse_float(p);
	if (!(d >= 1 && d <= 4294967295.0))
		parse_error_at(p, at, "a fractal's iterations must be at least 1, not %g", d);
	return d > 2147483647.0 ? 2147483647 : (int)d;
}

/* A 2-D vector (a complex number) as julia and magnet read it. */
static void parse_complex(struct parser *p, double c[2])
{
	struct value v = parse_expression(p);
	if (!val_is_numeric(&v))
		parse_error_at(p, v.pos, "expected a 2-D vector, found a %s", val_kind_name(v.kind));
	val_widen(&v, 2);
	c[0] = v.v[0];
	c[1] = v.v[1];
}

/* slope_args := VECTOR [',' LO ',' HI] [altitude VECTOR [',' LO ',' HI]]
 *   | point_at VECTOR [',' LO ',' HI] */
static void parse_slope_args(struct parser *p, struct pattern *pt)
{
	bool point_at = parse_accept_kw(p, KW_POINT_AT);
	pt->vec = parse_vector(p);
	if (point_at)
		pt->n[1] = 1;
	if (parse_accept(p, TOK_COMMA)) {
		pt->f[0] = parse_float(p);
		parse_expect(p, TOK_COMMA);
		pt->f[1] = parse_float(p);
	}
	if (point_at) {
		if (parse_peek(p)->kind == TOK_KEYWORD && parse_peek(p)->kw == KW_ALTITUDE)
			parse_error(p, "'altitude' cannot be used with 'point_at' in the slope pattern");
		return;
	}
	if (parse_accept_kw(p, KW_ALTITUDE)) {
		pt->vec2 = parse_vector(p);
		if (parse_accept(p, TOK_COMMA)) {
			pt->f[2] = parse_float(p);
			parse_expect(p, TOK_COMMA);
			pt->f[3] = parse_float(p);
		}
	}
}

/* pattern_type := PATTERN_KEYWORD pattern_arguments
 * Replaces *pt by the pattern at the current token with its arguments:
 *   gradient V | spiral1 N | spiral2 N | tiling N | julia V ',' N | mandel N
 *   | magnet (1|2) (mandel N | julia V ',' N) | object '{' (OBJECT | IDENT)
 *     (the list and the '}' are the caller's)
 *   | function '{' BODY '}' | pigment_pattern '{' PIGMENT_BODY '}'
 *   | image_pattern '{' IMAGE '}' | slope ('{' slope_args '}' | slope_args)
 *   | any other pattern name alone. */
void parse_pattern_type(struct parser *p, struct pattern *pt, enum pattern_use use)
{
	const struct token *t = parse_peek(p);
	struct srcpos at = t->pos;
	enum kw kw = (enum kw)t->kw;
	enum pattern_kind k = pattern_of_kw(kw);
	if (k == PAT_FACETS && use != PATTERN_IN_NORMAL)
		parse_error_at(p, at, "the facets pattern can only be used in a normal, not in a %s", use_names[use]);
	pattern_clear(pt);
	*pt = pattern_with_defaults(k);
	/* global_settings { noise_generator } read before the pattern is its
	 * generator (the renderer passes the scene's to the rest, which also
	 * covers a global_settings after the pattern, as in POV-Ray). */
	if (p->scene && p->scene->gs.noise_generator != 2)
		pt->noise_generator = p->scene->gs.noise_generator;
	if (k == PAT_OBJECT) {
		/* object '{' (IDENT | OBJECT) LIST_A [','] LIST_B '}': the list
		 * is the block's, so the caller reads it and the '}' (see
		 * struct body_state). */
		parse_advance(p);
		parse_expect(p, TOK_LBRACE);
		const struct token *ot = parse_peek(p);
		if (ot->kind == TOK_KEYWORD && parse_is_object_start((enum kw)ot->kw)) {
			pt->obj = parse_object(p, false);
		} else {
			const struct value *v = parse_ident_value(p);
			if (!v)
				parse_expected(p, "an object or an object identifier");
			if (v->kind != VAL_OBJECT)
				parse_wrong_kind(p, v, "an object");
			pt->obj = object_copy(v->obj);
			parse_advance(p);
		}
		return;
	}
	if (k == PAT_FUNCTION) {
		pt->fn = parse_function(p);
		return;
	}
	parse_advance(p);
	switch (k) {
	case PAT_GRADIENT: pt->vec = parse_vector(p); break;
	case PAT_SPIRAL1: case PAT_SPIRAL2: pt->n[0] = parse_int_of(parse_float(p)); break;
	case PAT_TILING: pt->n[0] = parse_int_in(p, "the tiling pattern's number", 1, 27); break;
	case PAT_JULIA:
		parse_complex(p, pt->fractal.c);
		parse_expect(p, TOK_COMMA);
		pt->fractal.iterations = parse_iterations(p);
		break;
	case PAT_MANDEL: pt->fractal.iterations = parse_iterations(p); break;
	case PAT_MAGNET:
		pt->fractal.magnet_type = parse_int_in(p, "the magnet type", 1, 2);
		if (parse_accept_kw(p, KW_MANDEL)) {
			pt->fractal.iterations = parse_iterations(p);
		} else if (parse_accept_kw(p, KW_JULIA)) {
			pt->fractal.julia = true;
			parse_complex(p, pt->fractal.c);
			parse_expect(p, TOK_COMMA);
			pt->fractal.iterations = parse_iterations(p);
		} else {
			parse_expected(p, "mandel or julia after the magnet type");
		}
		break;
	case PAT_PIGMENT:
		parse_expect(p, TOK_LBRACE);
		pt->pig = parse_pigment_body(p, TOK_RBRACE);
		break;
	case PAT_IMAGE:
		parse_expect(p, TOK_LBRACE);
		parse_image_mapping(p, &pt->img);
		parse_expect(p, TOK_RBRACE);
		break;
	case PAT_SLOPE:
		if (parse_accept(p, TOK_LBRACE)) {
			parse_slope_args(p, pt);
			parse_expect(p, TOK_RBRACE);
		} else {
			parse_slope_args(p, pt);
		}
		break;
	default:
		break;
	}
}

/* turb_items := { octaves N | omega F | lambda F } into t (true if one
 * was read). */
static bool parse_turb_item(struct parser *p, struct turbulence *t)
{
	if (parse_accept_kw(p, KW_OCTAVES)) {
		t->octaves = parse_int_in(p, "octaves", 1, 10);
		return true;
	}
	if (parse_accept_kw(p, KW_OMEGA)) {
		t->omega = parse_float(p);
		return true;
	}
	if (parse_accept_kw(p, KW_LAMBDA)) {
		t->lambda = parse_float(p);
		return true;
	}
	return false;
}

/* warp := warp '{' warp_item '}'
 * warp_item := repeat V [offset V] [flip V]
 *            | black_hole V ',' F { strength F | falloff F | inverse | repeat V | turbulence V }
 *            | turbulence V { turb_items }
 *            | cylindrical | spherical | toroidal { orientation V | dist_exp F | major_radius F }
 *            | planar [V ',' F] | cubic */
static void parse_warp(struct parser *p, struct pattern *pt)
{
	parse_advance(p); /* warp */
	parse_expect(p, TOK_LBRACE);
	struct pattern_op op;
	memset(&op, 0, sizeof op);
	op.turb.octaves = 6;
	op.turb.omega = 0.5;
	op.turb.lambda = 2.0;
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		parse_expected(p, "a warp type (repeat, black_hole, turbulence, cylindrical, spherical, toroidal, planar or cubic)");
	switch (t->kw) {
	case KW_REPEAT:
		parse_advance(p);
		op.kind = POP_REPEAT;
		op.v1 = parse_vector(p);
		for (;;) {
			if (parse_accept_kw(p, KW_OFFSET))
				op.v2 = parse_vector(p);
			else if (parse_accept_kw(p, KW_FLIP))
				op.v3 = parse_vector(p);
			else
				break;
		}
		break;
	case KW_BLACK_HOLE:
		parse_advance(p);
		op.kind = POP_BLACK_HOLE;
		op.v1 = parse_vector(p);
		parse_expect(p, TOK_COMMA);
		op.f1 = parse_float(p);
		op.f2 = 2; /* falloff */
		op.f3 = 1; /* strength */
		for (;;) {
			if (parse_accept_kw(p, KW_STRENGTH))
				op.f3 = parse_float(p);
			else if (parse_accept_kw(p, KW_FALLOFF))
				op.f2 = parse_float(p);
			else if (parse_accept_kw(p, KW_INVERSE))
				op.f4 = 1;
			else if (parse_accept_kw(p, KW_REPEAT))
				op.v2 = parse_vector(p);
			else if (parse_accept_kw(p, KW_TURBULENCE))
				op.turb.amount = op.v3 = parse_vector(p);
			else if (!parse_turb_item(p, &op.turb))
				break;
		}
		break;
	case KW_TURBULENCE:
		parse_advance(p);
		op.kind = POP_TURBULENCE;
		op.turb.amount = parse_vector(p);
		while (parse_turb_item(p, &op.turb))
			;
		break;
	case KW_CYLINDRICAL: case KW_SPHERICAL: case KW_TOROIDAL:
		op.kind = t->kw == KW_CYLINDRICAL ? POP_CYLINDRICAL : t->kw == KW_SPHERICAL ? POP_SPHERICAL : POP_TOROIDAL;
		parse_advance(p);
		op.v1 = v3(0, 0, 1);
		op.f2 = 1; /* major_radius */
		for (;;) {
			if (parse_accept_kw(p, KW_ORIENTATION))
				op.v1 = parse_vector(p);
			else if (parse_accept_kw(p, KW_DIST_EXP))
				op.f1 = parse_float(p);
			else if (op.kind == POP_TOROIDAL && parse_accept_kw(p, KW_MAJOR_RADIUS))
				op.f2 = parse_float(p);
			else
				break;
		}
		break;
	case KW_PLANAR:
		parse_advance(p);
		op.kind = POP_PLANAR;
		op.v1 = v3(0, 0, 1);
		if (parse_starts_expression(p)) {
			op.v1 = parse_vector(p);
			parse_expect(p, TOK_COMMA);
			op.f1 = parse_float(p);
		}
		break;
	case KW_CUBIC:
		parse_advance(p);
		op.kind = POP_CUBIC;
		break;
	default:
		parse_expected(p, "a warp type (repeat, black_hole, turbulence, cylindrical, spherical, toroidal, planar or cubic)");
	}
	parse_expect(p, TOK_RBRACE);
	pattern_add_op(pt, &op);
}

/* A kind-specific modifier used with another kind: POV-Ray's error. */
static _Noreturn void not_for_kind(struct parser *p, struct srcpos at, enum kw k, const char *kinds)
{
	parse_error_at(p, at, "'%s' can only be used with the %s pattern", kw_names[k], kinds);
}

static bool is_fractal(enum pattern_kind k)
{
	return k == PAT_JULIA || k == PAT_MANDEL || k == PAT_MAGNET;
}

/* pattern_modifier := turbulence (V|F) | octaves N | omega F | lambda F
 *   | frequency F | phase F | ramp_wave | triangle_wave | sine_wave
 *   | scallop_wave | cubic_wave | poly_wave [F] | noise_generator N
 *   | warp
 *   | the kinds' own: agate_turb F | brick_size V | mortar F | metric F
 *   | offset F | solid | form (V|N) | control0 F | control1 F | exponent N
 *   | interior N [',' F] | exterior N [',' F] | number_of_sides N
 *   | number_of_tiles N | pattern N | coords F | size F
 * Transformations are the caller's (they reach the block's map items).
 * Returns false, reading nothing, at anything else. */
bool parse_pattern_modifier(struct parser *p, struct pattern *pt)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	struct srcpos at = t->pos;
	enum kw k = (enum kw)t->kw;
	enum pattern_kind pk = pt->kind;
	switch (k) {
	case KW_TURBULENCE: parse_advance(p); pt->has_turbulence = true; pt->turb.amount = parse_vector(p); return true;
	case KW_OCTAVES: case KW_OMEGA: case KW_LAMBDA: return parse_turb_item(p, &pt->turb);
	case KW_FREQUENCY: parse_advance(p); pt->frequency = parse_float(p); return true;
	case KW_PHASE: parse_advance(p); pt->phase = parse_float(p); return true;
	case KW_RAMP_WAVE: parse_advance(p); pt->wave = WAVE_RAMP; return true;
	case KW_TRIANGLE_WAVE: parse_advance(p); pt->wave = WAVE_TRIANGLE; return true;
	case KW_SINE_WAVE: parse_advance(p); pt->wave = WAVE_SINE; return true;
	case KW_SCALLOP_WAVE: parse_advance(p); pt->wave = WAVE_SCALLOP; return true;
	case KW_CUBIC_WAVE: parse_advance(p); pt->wave = WAVE_CUBIC; return true;
	case KW_POLY_WAVE:
		parse_advance(p);
		pt->wave = WAVE_POLY;
		pt->wave_exponent = 1;
		if (parse_starts_expression(p))
			pt->wave_exponent = parse_float(p);
		return true;
	case KW_NOISE_GENERATOR:
		parse_advance(p);
		pt->noise_generator = parse_int_in(p, "noise_generator", 1, 3);
		return true;
	case KW_WARP: parse_warp(p, pt); return true;
	case KW_AGATE_TURB:
		if (pk != PAT_AGATE) not_for_kind(p, at, k, "agate");
		parse_advance(p);
		pt->f[0] = parse_float(p);
		return true;
	case KW_BRICK_SIZE:
		if (pk != PAT_BRICK) not_for_kind(p, at, k, "brick");
		parse_advance(p);
		pt->vec = parse_vector(p);
		return true;
	case KW_MORTAR:
		if (pk != PAT_BRICK) not_for_kind(p, at, k, "brick");
		parse_advance(p);
		pt->vec2.x = parse_float(p);
		return true;
	case KW_METRIC:
		if (pk != PAT_CRACKLE && pk != PAT_FACETS) not_for_kind(p, at, k, "crackle or facets");
		parse_advance(p);
		pt->f[0] = parse_float(p);
		return true;
	case KW_OFFSET:
		if (pk != PAT_CRACKLE) not_for_kind(p, at, k, "crackle");
		parse_advance(p);
		pt->f[1] = parse_float(p);
		return true;
	case KW_SOLID:
		if (pk != PAT_CRACKLE) not_for_kind(p, at, k, "crackle");
		parse_advance(p);
		pt->n[0] = 1;
		return true;
	case KW_FORM:
		parse_advance(p);
		if (pk == PAT_CRACKLE)
			pt->form = parse_vector(p);
		else if (pk == PAT_PAVEMENT)
			pt->n[5] = parse_int_in(p, "a pavement's form", 0, 3);
		else
			not_for_kind(p, at, k, "crackle or pavement");
		return true;
	case KW_CONTROL0: case KW_CONTROL1:
		if (pk != PAT_QUILTED) not_for_kind(p, at, k, "quilted");
		parse_advance(p);
		pt->f[k == KW_CONTROL0 ? 0 : 1] = parse_float(p);
		return true;
	case KW_EXPONENT:
		if (pk != PAT_JULIA && pk != PAT_MANDEL) not_for_kind(p, at, k, "mandel or julia");
		parse_advance(p);
		pt->fractal.exponent = parse_int_in(p, "a fractal's exponent", 2, 33);
		return true;
	case KW_INTERIOR: case KW_EXTERIOR: {
		bool in = k == KW_INTERIOR;
		if (pk == PAT_PAVEMENT) {
			parse_advance(p);
			pt->n[in ? 4 : 3] = parse_int_in(p, in ? "a pavement's interior" : "a pavement's exterior", 0, 2);
			return true;
		}
		if (!is_fractal(pk))
			return false; /* interior { } of an object or a material */
		parse_advance(p);
		int type = parse_int_in(p, in ? "the interior type" : "the exterior type", 0, in ? 6 : 8);
		double factor = 1;
		if (parse_accept(p, TOK_COMMA))
			factor = parse_float(p);
		if (in) {
			pt->fractal.interior_type = type;
			pt->fractal.interior_factor = factor;
		} else {
			pt->fractal.exterior_type = type;
			pt->fractal.exterior_factor = factor;
		}
		return true;
	}
	case KW_NUMBER_OF_SIDES: case KW_NUMBER_OF_TILES: case KW_PATTERN: {
		if (pk != PAT_PAVEMENT) not_for_kind(p, at, k, "pavement");
		parse_advance(p);
		int i = k == KW_NUMBER_OF_SIDES ? 0 : k == KW_NUMBER_OF_TILES ? 1 : 2;
		if (i == 0) {
			struct srcpos vat = parse_peek(p)->pos;
			int s = parse_int_of(parse_float(p));
			if (s != 3 && s != 4 && s != 6)
				parse_error_at(p, vat, "number_of_sides must be 3, 4 or 6, not %d", s);
			pt->n[0] = s;
		} else {
			pt->n[i] = parse_int_in(p, i == 1 ? "number_of_tiles" : "a pavement's pattern", 1, i == 1 ? 6 : 35);
		}
		return true;
	}
	case KW_COORDS: case KW_SIZE:
		if (pk != PAT_FACETS) not_for_kind(p, at, k, "facets");
		parse_advance(p);
		if (k == KW_COORDS)
			pt->vec.y = parse_float(p);
		else
			pt->vec.x = parse_float(p);
		return true;
	default:
		return false;
	}
}

/* The checks that need all of a pattern's modifiers, made at the token that
 * closes its body: a pavement's pattern number must be one of its
 * polyforms (POV-Ray: "pattern value for pavement is out of range"). */
void parse_pattern_end(struct parser *p, const struct pattern *pt)
{
	if (pt->kind != PAT_PAVEMENT)
		return;
	int n = pavement_pattern_count(pt->n[0], pt->n[1]);
	if (n == 0)
		parse_error(p, "a pavement of hexagons has 1 to 5 tiles, not %d", pt->n[1]);
	if (pt->n[2] > n)
		parse_error(p, "a pavement of %d %s has %d pattern%s, not %d", pt->n[1],
		            pt->n[0] == 3 ? "triangles" : pt->n[0] == 4 ? "squares" : "hexagons", n, n == 1 ? "" : "s",
		            pt->n[2]);
}

/* pattern_block := '{' pattern_type { pattern_modifier | transformation } '}' */
void parse_pattern_block(struct parser *p, struct pattern *pt)
{
	parse_expect(p, TOK_LBRACE);
	bool in_object = false;
	for (;;) {
		if (in_object && parse_accept(p, TOK_RBRACE)) {
			in_object = false;
			continue;
		}
		if (parse_peek(p)->kind == TOK_RBRACE) {
			parse_pattern_end(p, pt);
			parse_advance(p);
			break;
		}
		struct xform xf;
		enum pattern_kind pk;
		if (parse_transform_item(p, &xf)) {
			pattern_transform(pt, &xf);
			continue;
		}
		if (parse_at_pattern(p, &pk)) {
			parse_pattern_type(p, pt, PATTERN_IN_PIGMENT);
			in_object = pk == PAT_OBJECT;
			continue;
		}
		if (pt->kind != PAT_NONE && parse_pattern_modifier(p, pt))
			continue;
		parse_expected(p, pt->kind == PAT_NONE ? "a pattern" : "a pattern modifier or '}'");
	}
	if (pt->kind == PAT_NONE)
		parse_error(p, "a pattern function needs a pattern");
}

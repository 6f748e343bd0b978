/* texture_parse.c: pigments, normals, textures (plain, patterned, layered,
 * material_map), the block patterns' lists, the maps (color_map,
 * pigment_map, normal_map, slope_map, texture_map), materials and
 * #default; the patterns themselves, with their parameters and modifiers,
 * are pattern_parse.c's. Each grammar function names its production above
 * it.
 *
 * A block (pigment, normal, texture) is parsed by one body function that
 * stops at a given closing token, so that `pigment { BODY }` and a map
 * entry `[ VALUE BODY ]` share it. What a block refers to while it is
 * being read is held through a heap holder registered with parse_own, so
 * an error anywhere frees it. */
#include "image/image.h"
#include "lang/parser.h"

#include <stdlib.h>
#include <string.h>

/* POV-Ray's limit on the entries of a map. */
enum { MAP_MAX_ENTRIES = 256 };

static void pigment_body(struct parser *p, struct pigment **pig, enum tok_kind end);
static void normal_body(struct parser *p, struct normal **nrm, enum tok_kind end);
static void texture_body(struct parser *p, struct texture **tex, enum tok_kind end);
static struct blend_map *parse_map(struct parser *p, enum map_kind kind, enum pattern_kind pk);

/* ---- holders: what a block refers to while it is read ---- */

static void free_pigment_holder(void *h)
{
	pigment_unref(*(struct pigment **)h);
	free(h);
}

static void free_normal_holder(void *h)
{
	normal_unref(*(struct normal **)h);
	free(h);
}

static void free_map_cb(void *m) { blend_map_unref(m); }

static void *holder_new(size_t size)
{
	void *h = calloc(1, size);
	if (!h) abort();
	return h;
}

/* A new pigment read by pigment_body up to `end`, starting from `from`
 * (a reference is taken) or from black. The caller owns the result. */
static struct pigment *read_pigment(struct parser *p, struct pigment *from, enum tok_kind end)
{
	struct pigment **h = holder_new(sizeof *h);
	*h = from ? pigment_ref(from) : pigment_new();
	int slot = parse_own(p, h, free_pigment_holder);
	pigment_body(p, h, end);
	struct pigment *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

struct pigment *parse_pigment_body(struct parser *p, enum tok_kind end)
{
	return read_pigment(p, NULL, end);
}

static struct normal *read_normal(struct parser *p, struct normal *from, enum tok_kind end)
{
	struct normal **h = holder_new(sizeof *h);
	*h = from ? normal_ref(from) : NULL;
	int slot = parse_own(p, h, free_normal_holder);
	normal_body(p, h, end);
	struct normal *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

static struct texture *read_texture(struct parser *p, enum tok_kind end)
{
	struct texture **h = holder_new(sizeof *h);
	int slot = parse_own(p, h, parse_free_texture_holder);
	texture_body(p, h, end);
	struct texture *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

/* Make *pig (and the others) one this holder may change alone. */
static struct pigment *own_pigment(struct pigment **pig)
{
	if ((*pig)->refs > 1) {
		struct pigment *c = pigment_copy(*pig);
		pigment_unref(*pig);
		*pig = c;
	}
	return *pig;
}

static struct normal *own_normal(struct normal **n)
{
	if (!*n)
		*n = normal_new(PAT_NONE);
	else if ((*n)->refs > 1) {
		struct normal *c = normal_copy(*n);
		normal_unref(*n);
		*n = c;
	}
	return *n;
}

static struct texture *own_texture(struct texture **t)
{
	if ((*t)->refs > 1) {
		struct texture *c = texture_copy(*t);
		texture_unref(*t);
		*t = c;
	}
	return *t;
}

static struct texture *default_texture(struct parser *p)
{
	return p->default_tex ? texture_copy(p->default_tex) : texture_new();
}

/* ---- colours ---- */

/* A numeric value as a colour, as `color V` reads it: a float sets all
 * five components, a vector is padded with zeros. */
static struct rgbft value_color(struct parser *p, struct value *v)
{
	if (!val_is_numeric(v))
		parse_error_at(p, v->pos, "expected a color, found a %s", val_kind_name(v->kind));
	if (v->kind == VAL_FLOAT)
		return (struct rgbft){v->v[0], v->v[0], v->v[0], v->v[0], v->v[0]};
	val_widen(v, 5);
	return (struct rgbft){v->v[0], v->v[1], v->v[2], v->v[3], v->v[4]};
}

/* ---- block lists: `checker color A color B`, `hexagon pigment{} ...` ---- */

/* Before an entry of a block pattern's list is read: an error at the
 * current token when the list is full. `what` names what it holds. */
static void list_room(struct parser *p, const struct blend_map *m, const struct pattern *pt, const char *what)
{
	int max = pattern_block_entries(pt->kind);
	if (m && m->n >= max)
		parse_error(p, "the %s pattern takes at most %d %s", pattern_name(pt->kind), max, what);
}

/* A new entry of a block pattern's list in *mp (created, of the given
 * kind, with room for the pattern's number of entries on the first); the
 * caller has checked there is room and fills the entry. */
static struct map_entry *list_entry(struct blend_map **mp, enum map_kind kind, const struct pattern *pt)
{
	if (!*mp) {
		*mp = blend_map_new(kind, pattern_block_entries(pt->kind));
		(*mp)->n = 0;
	}
	struct blend_map *m = *mp;
	struct map_entry *e = &m->e[m->n];
	memset(e, 0, sizeof *e);
	e->value = m->n;
	m->n++;
	return e;
}

/* Complete a block pattern's list with POV-Ray's defaults for the entries
 * not written: the pattern's default colours in a list of colours, black
 * in a list of pigments (measured: `checker pigment { rgb 0.25 }` is black
 * in its second cell, for every block pattern). */
static void finish_list(struct parser *p, struct blend_map *m, const struct pattern *pt)
{
	int max = pattern_block_entries(pt->kind);
	if (!m || !max)
		return;
	for (int i = m->n; i < max; i++) {
		struct map_entry *e = &m->e[i];
		memset(e, 0, sizeof *e);
		e->value = i;
		if (m->kind == MAP_PIGMENT) {
			e->item = pigment_new();
		} else if (m->kind == MAP_COLOR) {
			e->color = pattern_block_default(pt->kind, i);
		} else if (m->kind == MAP_TEXTURE) {
			e->item = default_texture(p);
		}
	}
	m->n = max;
}

/* ---- pigment ---- */

/* A map given to a block: a map identifier of the right kind or a map
 * statement. `what` names the block for messages. */
static void set_map(struct parser *p, struct blend_map **dst, struct blend_map *m)
{
	(void)p;
	blend_map_unref(*dst);
	*dst = m;
}

static bool is_map_kw(enum kw k, enum map_kind *kind)
{
	switch (k) {
	case KW_COLOR_MAP: case KW_COLOUR_MAP: *kind = MAP_COLOR; return true;
	case KW_PIGMENT_MAP: *kind = MAP_PIGMENT; return true;
	case KW_NORMAL_MAP: *kind = MAP_NORMAL; return true;
	case KW_SLOPE_MAP: *kind = MAP_SLOPE; return true;
	case KW_TEXTURE_MAP: *kind = MAP_TEXTURE; return true;
	default: return false;
	}
}

static const char *map_kind_name(enum map_kind k)
{
	switch (k) {
	case MAP_COLOR: return "color_map";
	case MAP_PIGMENT: return "pigment_map";
	case MAP_NORMAL: return "normal_map";
	case MAP_SLOPE: return "slope_map";
	case MAP_TEXTURE: return "texture_map";
	}
	return "map";
}

/* A map statement for a block whose pattern is pk: block patterns take
 * lists, not maps (POV-Ray's rule). */
static struct blend_map *block_map(struct parser *p, enum map_kind kind, const struct pattern *pt)
{
	if (pattern_is_block(pt->kind))
		parse_error(p, "the %s pattern takes a list of entries, not a %s", pattern_name(pt->kind),
		            map_kind_name(kind));
	if (pt->kind == PAT_NONE)
		parse_error(p, "a %s needs a pattern before it", map_kind_name(kind));
	return parse_map(p, kind, pt->kind);
}

/* uv_prefix := { uv_mapping }
 * POV-Ray takes uv_mapping only first in a pigment, normal or texture
 * block, before or just after its identifier; the flag is applied when
 * the block ends, so the block's own transformations move the uv-mapped
 * pattern and later ones do not (see pattern_transform). Returns whether
 * one was read. */
static bool read_uv_prefix(struct parser *p)
{
	bool uv = false;
	while (parse_accept_kw(p, KW_UV_MAPPING))
		uv = true;
	return uv;
}

/* A uv_mapping after the block's first items: POV-Ray's error. */
static void late_uv_mapping(struct parser *p, const char *block)
{
	if (parse_is_kw(p, KW_UV_MAPPING))
		parse_error(p, "uv_mapping must come first in a %s, before everything but an identifier", block);
}

/* pigment_body := uv_prefix [IDENT] uv_prefix [pigment_type] { pigment_modifier }
 * pigment_type := COLOR | pattern_type | image_map '{' IMAGE '}'
 * pigment_modifier := pattern_modifier | transformation | COLOR (a block
 *   pattern's list) | pigment '{' '}' (the same) | color_map | colour_map
 *   | pigment_map | MAP_IDENT | quick_color COLOR | quick_colour COLOR
 * Reads up to and including `end` into *pig (replaced or made private). */
static void pigment_body(struct parser *p, struct pigment **pig, enum tok_kind end)
{
	bool uv = read_uv_prefix(p);
	const struct value *v = parse_ident_value(p);
	if (v && v->kind == VAL_PIGMENT) {
		pigment_unref(*pig);
		*pig = pigment_ref(v->pig);
		parse_advance(p);
	}
	uv |= read_uv_prefix(p);
	bool in_object = false; /* inside object { OBJ ... }: its list, then '}' */
	bool leading = true;    /* nothing read yet but the identifier */
	for (;;) {
		if (in_object && parse_accept(p, TOK_RBRACE)) {
			in_object = false;
			continue;
		}
		if (parse_peek(p)->kind == end) {
			parse_pattern_end(p, &(*pig)->pat);
			parse_advance(p);
			break;
		}
		bool first = leading;
		leading = false;
		const struct token *t = parse_peek(p);
		struct xform xf;
		enum pattern_kind pk;
		enum map_kind mk;
		if (t->kind == TOK_KEYWORD && (t->kw == KW_COLOR || t->kw == KW_COLOUR) && (*pig)->kind == PIGMENT_SOLID) {
			/* The common `pigment { color C }`: what the tests below
			 * would find (no transformation or pattern starts with
			 * `color`, and it starts an expression). */
			struct pigment *pg = own_pigment(pig);
			pg->color = parse_color(p);
			continue;
		}
		if (parse_transform_item(p, &xf)) {
			*pig = pigment_transform(*pig, &xf);
			continue;
		}
		if (parse_at_pattern(p, &pk)) {
			struct pigment *pg = own_pigment(pig);
			blend_map_unref(pg->map);
			pg->map = NULL;
			pg->kind = PIGMENT_PATTERN;
			parse_pattern_type(p, &pg->pat, PATTERN_IN_PIGMENT);
			in_object = pg->pat.kind == PAT_OBJECT;
			continue;
		}
		if (t->kind == TOK_IDENT) {
			v = parse_ident_value(p);
			if (v->kind == VAL_MAP) {
				struct pigment *pg = own_pigment(pig);
				if (v->map->kind != MAP_COLOR && v->map->kind != MAP_PIGMENT)
					parse_wrong_kind(p, v, "a color_map or pigment_map");
				if (pattern_is_block(pg->pat.kind) || pg->pat.kind == PAT_NONE)
					parse_error(p, "a map identifier needs a continuous pattern before it");
				set_map(p, &pg->map, blend_map_ref(v->map));
				parse_advance(p);
				continue;
			}
			if (!val_is_numeric(v))
				parse_wrong_kind(p, v, "a color or a map in a pigment");
		}
		if (parse_starts_expression(p)) {
			struct pigment *pg = own_pigment(pig);
			if (first && pg->kind != PIGMENT_SOLID) {
				/* A colour first makes the pigment that colour, whatever
				 * it was (POV-Ray 3.7: `pigment { checker } pigment { rgb
				 * <1, 0, 0> }` is plain red). */
				blend_map_unref(pg->map);
				pg->map = NULL;
				pattern_clear(&pg->pat);
				pg->kind = PIGMENT_SOLID;
				pg->quick = false;
			}
			if (pg->kind == PIGMENT_SOLID) {
				pg->color = parse_color(p);
				continue;
			}
			if (!pattern_is_block(pg->pat.kind))
				parse_error(p, "a color cannot follow the %s pattern: use a color_map", pattern_name(pg->pat.kind));
			list_room(p, pg->map, &pg->pat, "colors or pigments");
			if (pg->map && pg->map->kind != MAP_COLOR)
				parse_error(p, "this %s list holds pigments: a color cannot be mixed in", pattern_name(pg->pat.kind));
			struct rgbft c = parse_color(p);
			parse_accept(p, TOK_COMMA);
			list_entry(&pg->map, MAP_COLOR, &pg->pat)->color = c;
			continue;
		}
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a color, a pattern, a pigment modifier or '}'");
		if (t->kw == KW_PIGMENT) {
			struct pigment *pg = own_pigment(pig);
			if (!pattern_is_block(pg->pat.kind))
				parse_error(p, "a pigment inside a pigment must be an entry of a block pattern's list (checker, hexagon, brick, ...)");
			list_room(p, pg->map, &pg->pat, "colors or pigments");
			if (pg->map && pg->map->kind != MAP_PIGMENT)
				parse_error(p, "this %s list holds colors: a pigment cannot be mixed in", pattern_name(pg->pat.kind));
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			struct pigment *item = read_pigment(p, NULL, TOK_RBRACE);
			list_entry(&pg->map, MAP_PIGMENT, &pg->pat)->item = item;
			parse_accept(p, TOK_COMMA);
			continue;
		}
		if (is_map_kw((enum kw)t->kw, &mk) && (mk == MAP_COLOR || mk == MAP_PIGMENT)) {
			struct pigment *pg = own_pigment(pig);
			struct blend_map *m = block_map(p, mk, &pg->pat);
			set_map(p, &pg->map, m);
			continue;
		}
		switch (t->kw) {
		case KW_QUICK_COLOR: case KW_QUICK_COLOUR: {
			parse_advance(p);
			struct rgbft c = parse_color(p);
			struct pigment *pg = own_pigment(pig);
			if (pg->kind != PIGMENT_SOLID) {
				pg->color = c; /* a solid colour keeps its own */
				pg->quick = true;
			}
			continue;
		}
		case KW_IMAGE_MAP: {
			struct pigment *pg = own_pigment(pig);
			blend_map_unref(pg->map);
			pg->map = NULL;
			pattern_clear(&pg->pat);
			pg->pat = pattern_make(PAT_IMAGE);
			pg->kind = PIGMENT_IMAGE;
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			parse_image_mapping(p, &pg->pat.img);
			if (p->scene && p->scene->gs.assumed_gamma != 1) {
				char err[1024];
				if (!image_mapping_to_working(&pg->pat.img, p->scene->gs.assumed_gamma, err, sizeof err))
					parse_error(p, "cannot read image file \"%s\": %s", pg->pat.img.img->path, err);
			}
			parse_expect(p, TOK_RBRACE);
			continue;
		}
		default:
			break;
		}
		late_uv_mapping(p, "pigment");
		if (parse_pattern_modifier(p, &own_pigment(pig)->pat))
			continue;
		parse_expected(p, "a color, a pattern, a pigment modifier or '}'");
	}
	struct pigment *pg = *pig;
	if (pg->map && pattern_is_block(pg->pat.kind) && pg->map->n < pattern_block_entries(pg->pat.kind))
		finish_list(p, own_pigment(pig)->map, &pg->pat);
	if (uv && (*pig)->kind != PIGMENT_SOLID)
		own_pigment(pig)->pat.uv_mapping = true;
}

/* pigment := pigment '{' pigment_body '}'
 * Reads into *pig: a pigment identifier replaces it, other items modify
 * it (made private first). */
void parse_pigment(struct parser *p, struct pigment **pig)
{
	parse_advance(p); /* pigment */
	parse_expect(p, TOK_LBRACE);
	if (!*pig)
		*pig = pigment_new();
	pigment_body(p, pig, TOK_RBRACE);
}

/* ---- normal ---- */

/* normal_body := uv_prefix [IDENT] uv_prefix [pattern_type [[','] AMOUNT]] { normal_modifier }
 * normal_modifier := pattern_modifier | transformation | bump_size F
 *   | accuracy F | normal_map | slope_map | MAP_IDENT | normal '{' '}' (a
 *   block pattern's list) | bump_map '{' IMAGE { bump_size F } '}' */
static void normal_body(struct parser *p, struct normal **nrm, enum tok_kind end)
{
	bool uv = read_uv_prefix(p);
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_NORMAL)
			parse_wrong_kind(p, v, "a normal");
		normal_unref(*nrm);
		*nrm = normal_ref(v->nrm);
		parse_advance(p);
	}
	uv |= read_uv_prefix(p);
	own_normal(nrm);
	bool in_object = false; /* inside object { OBJ ... }: its list, then '}' */
	for (;;) {
		if (in_object && parse_accept(p, TOK_RBRACE)) {
			in_object = false;
			continue;
		}
		if (parse_peek(p)->kind == end) {
			parse_pattern_end(p, &(*nrm)->pat);
			parse_advance(p);
			break;
		}
		const struct token *t = parse_peek(p);
		struct xform xf;
		enum pattern_kind pk;
		enum map_kind mk;
		if (parse_transform_item(p, &xf)) {
			*nrm = normal_transform(*nrm, &xf);
			continue;
		}
		if (parse_at_pattern(p, &pk)) {
			struct normal *n = own_normal(nrm);
			blend_map_unref(n->map);
			n->map = NULL;
			parse_pattern_type(p, &n->pat, PATTERN_IN_NORMAL);
			in_object = n->pat.kind == PAT_OBJECT;
			/* The amount: `bumps 0.5`, `mandel 50, 0.3`, `spiral1 3, -0.5`. */
			if (!in_object && (parse_accept(p, TOK_COMMA) || parse_starts_expression(p)))
				n->amount = parse_float(p);
			continue;
		}
		if (t->kind == TOK_IDENT) {
			v = parse_ident_value(p);
			if (v->kind != VAL_MAP)
				parse_wrong_kind(p, v, "a normal_map or slope_map");
			struct normal *n = own_normal(nrm);
			if (v->map->kind != MAP_NORMAL && v->map->kind != MAP_SLOPE)
				parse_wrong_kind(p, v, "a normal_map or slope_map");
			set_map(p, &n->map, blend_map_ref(v->map));
			parse_advance(p);
			continue;
		}
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a pattern, a normal modifier or '}'");
		if (is_map_kw((enum kw)t->kw, &mk) && (mk == MAP_NORMAL || mk == MAP_SLOPE)) {
			struct normal *n = own_normal(nrm);
			set_map(p, &n->map, block_map(p, mk, &n->pat));
			continue;
		}
		switch (t->kw) {
		case KW_BUMP_SIZE: parse_advance(p); own_normal(nrm)->amount = parse_float(p); continue;
		case KW_ACCURACY: parse_advance(p); own_normal(nrm)->accuracy = parse_float(p); continue;
		case KW_NORMAL: {
			struct normal *n = own_normal(nrm);
			if (!pattern_is_block(n->pat.kind))
				parse_error(p, "a normal inside a normal must be an entry of a block pattern's list (checker, hexagon, brick, ...)");
			list_room(p, n->map, &n->pat, "normals");
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			struct normal *item = read_normal(p, NULL, TOK_RBRACE);
			list_entry(&n->map, MAP_NORMAL, &n->pat)->item = item;
			parse_accept(p, TOK_COMMA);
			continue;
		}
		case KW_BUMP_MAP: {
			struct normal *n = own_normal(nrm);
			blend_map_unref(n->map);
			n->map = NULL;
			pattern_clear(&n->pat);
			n->pat = pattern_make(PAT_IMAGE);
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			parse_image_mapping(p, &n->pat.img);
			while (!parse_accept(p, TOK_RBRACE)) {
				if (parse_accept_kw(p, KW_BUMP_SIZE))
					n->amount = parse_float(p);
				else
					parse_expected(p, "a bump_map modifier or '}'");
			}
			continue;
		}
		default:
			break;
		}
		late_uv_mapping(p, "normal");
		if (parse_pattern_modifier(p, &own_normal(nrm)->pat))
			continue;
		parse_expected(p, "a pattern, a normal modifier or '}'");
	}
	struct normal *n = *nrm;
	if (n->map && pattern_is_block(n->pat.kind) && n->map->n < pattern_block_entries(n->pat.kind))
		finish_list(p, n->map, &n->pat);
	if (uv)
		own_normal(nrm)->pat.uv_mapping = true;
}

/* normal := normal '{' normal_body '}' : replaces or modifies *nrm (NULL:
 * none yet). */
void parse_normal(struct parser *p, struct normal **nrm)
{
	parse_advance(p); /* normal */
	parse_expect(p, TOK_LBRACE);
	normal_body(p, nrm, TOK_RBRACE);
}

/* ---- maps ---- */

/* color_entry := '[' F [','] COLOR ']' | '[' F [','] F [','] COLOR [','] COLOR ']'
 * (the second, old form, is two entries). */
static void color_entry(struct parser *p, struct blend_map *m, double value, int *cap)
{
	struct rgbft c;
	double v2 = 0;
	bool two = false;
	if (parse_is_kw(p, KW_COLOR) || parse_is_kw(p, KW_COLOUR)) {
		c = parse_color(p);
	} else {
		struct value e = parse_expression(p);
		if (e.kind == VAL_FLOAT && !parse_is(p, TOK_RBRACKET)) {
			two = true;
			v2 = e.v[0];
			parse_accept(p, TOK_COMMA);
			c = parse_color(p);
		} else {
			c = value_color(p, &e);
		}
	}
	if (m->n + (two ? 2 : 1) > *cap) {
		*cap *= 2;
		m->e = realloc(m->e, (size_t)*cap * sizeof *m->e);
		if (!m->e) abort();
	}
	struct map_entry *e = &m->e[m->n++];
	memset(e, 0, sizeof *e);
	e->value = value;
	e->color = c;
	if (two) {
		parse_accept(p, TOK_COMMA);
		struct rgbft c2 = parse_color(p);
		e = &m->e[m->n++];
		memset(e, 0, sizeof *e);
		e->value = v2;
		e->color = c2;
	}
}

/* layered := texture '{' texture_body '}' { texture '{' texture_body '}' }
 * Several textures in a row: the last is the top layer. Reads up to `end`
 * when `end` is not TOK_EOF. Returns the top layer (one reference). */
static struct texture *read_layers(struct parser *p, struct texture *under, enum tok_kind end);

/* map := MAP_KEYWORD '{' ( MAP_IDENT | { '[' entry ']' } ) '}'
 * entry := F [','] (COLOR | PIGMENT_BODY | NORMAL_BODY | '<' H ',' S '>'
 *   | TEXTURE_BODY); for the average
 *   pattern the value (a weight) may be left out (1). At most 256 entries.
 * Returns a new map (one reference). */
static struct blend_map *parse_map(struct parser *p, enum map_kind kind, enum pattern_kind pk)
{
	const char *name = kw_names[parse_peek(p)->kw];
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_MAP || v->map->kind != kind) {
			char want[40];
			snprintf(want, sizeof want, "a %s", map_kind_name(kind));
			parse_wrong_kind(p, v, want);
		}
		struct blend_map *m = blend_map_ref(v->map);
		parse_advance(p);
		int slot = parse_own(p, m, free_map_cb);
		parse_expect(p, TOK_RBRACE);
		parse_release(p, slot);
		return m;
	}
	int cap = 8;
	struct blend_map *m = blend_map_new(kind, cap);
	m->n = 0;
	int slot = parse_own(p, m, free_map_cb);
	while (parse_is(p, TOK_LBRACKET)) {
		struct srcpos at = parse_peek(p)->pos;
		if (m->n >= MAP_MAX_ENTRIES)
			parse_error_at(p, at, "a %s has at most %d entries", name, MAP_MAX_ENTRIES);
		parse_advance(p);
		double value = 1;
		bool weight_optional = pk == PAT_AVERAGE;
		bool has_value = true;
		if (weight_optional) {
			const struct token *t = parse_peek(p);
			if (t->kind == TOK_IDENT) {
				const struct value *iv = parse_ident_value(p);
				has_value = iv->kind == VAL_FLOAT;
			} else {
				has_value = parse_starts_expression(p) && kind != MAP_COLOR;
			}
		}
		if (has_value) {
			value = parse_float(p);
			parse_accept(p, TOK_COMMA);
		}
		if (kind == MAP_COLOR) {
			color_entry(p, m, value, &cap);
			if (m->n > MAP_MAX_ENTRIES)
				parse_error_at(p, at, "a %s has at most %d entries", name, MAP_MAX_ENTRIES);
			parse_expect(p, TOK_RBRACKET);
			continue;
		}
		if (m->n == cap) {
			cap *= 2;
			m->e = realloc(m->e, (size_t)cap * sizeof *m->e);
			if (!m->e) abort();
		}
		struct map_entry *e = &m->e[m->n];
		memset(e, 0, sizeof *e);
		e->value = value;
		switch (kind) {
		case MAP_SLOPE: {
			struct value sv = parse_expression(p);
			if (!val_is_numeric(&sv))
				parse_error_at(p, sv.pos, "expected a <height, slope> vector, found a %s", val_kind_name(sv.kind));
			val_widen(&sv, 2);
			e->slope[0] = sv.v[0];
			e->slope[1] = sv.v[1];
			m->n++;
			parse_expect(p, TOK_RBRACKET);
			break;
		}
		case MAP_PIGMENT: {
			/* `[v]` alone is a hole: transparent. */
			if (!parse_accept(p, TOK_RBRACKET))
				e->item = read_pigment(p, NULL, TOK_RBRACKET);
			m->n++;
			break;
		}
		case MAP_NORMAL:
			if (!parse_accept(p, TOK_RBRACKET))
				e->item = read_normal(p, NULL, TOK_RBRACKET);
			m->n++;
			break;
		case MAP_TEXTURE:
			/* A texture body, as in POV-Ray: `[v texture { }]` is an
			 * error there; a layered texture comes in as an identifier. */
			e->item = read_texture(p, TOK_RBRACKET);
			m->n++;
			break;
		case MAP_COLOR:
			break;
		}
	}
	if (m->n == 0)
		parse_expected(p, "'[' and the map's first entry");
	parse_expect(p, TOK_RBRACE);
	parse_release(p, slot);
	return m;
}

/* A map as a declared value: color_map, colour_map, pigment_map,
 * normal_map, slope_map or texture_map at the current token. */
struct blend_map *parse_map_value(struct parser *p)
{
	enum map_kind mk;
	if (!is_map_kw((enum kw)parse_peek(p)->kw, &mk))
		parse_expected(p, "a map");
	return parse_map(p, mk, PAT_NONE);
}

/* ---- texture ---- */

/* The texture for a `texture {` statement inside a plain texture item
 * sequence: a texture identifier, or the default. */

/* Apply a texture-level uv_mapping to what the texture holds (whole: the
 * texture itself counts as uv-mapped, so nothing layers over it). */
void texture_uv_mapping(struct texture **tex, bool whole)
{
	struct texture *t = own_texture(tex);
	if (whole)
		t->uv_mapped = true;
	if (t->kind != TEX_PLAIN) {
		t->pat.uv_mapping = true;
		return;
	}
	if (t->pigment) {
		struct pigment *pg = own_pigment(&t->pigment);
		pg->pat.uv_mapping = true;
	}
	if (t->normal)
		own_normal(&t->normal)->pat.uv_mapping = true;
}

/* texture_body := uv_prefix [IDENT] uv_prefix { PNF_IDENT } { texture_item }
 * texture_item := pigment | normal | finish | transformation
 *   | pattern_type { pattern_modifier | texture_map | MAP_IDENT
 *                    | texture '{' '}' (a block pattern's list) }
 *   | material_map '{' IMAGE { texture } '}'
 *   | tiles texture '{' '}' tile2 texture '{' '}'
 * Replaces *tex with what is read (a new reference). */
static void texture_body(struct parser *p, struct texture **tex, enum tok_kind end)
{
	texture_unref(*tex);
	*tex = NULL;
	bool uv = read_uv_prefix(p);
	const struct value *v = parse_ident_value(p);
	if (v && v->kind == VAL_TEXTURE) {
		*tex = texture_ref(v->tex);
		parse_advance(p);
	} else {
		/* A texture statement starts from the defaults, not from what
		 * the object had. */
		*tex = default_texture(p);
	}
	uv |= read_uv_prefix(p);
	bool in_object = false; /* inside object { OBJ ... }: its list, then '}' */
	for (;;) {
		if (in_object && parse_accept(p, TOK_RBRACE)) {
			in_object = false;
			continue;
		}
		if (parse_peek(p)->kind == end) {
			parse_pattern_end(p, &(*tex)->pat);
			parse_advance(p);
			break;
		}
		const struct token *t = parse_peek(p);
		struct xform xf;
		enum pattern_kind pk;
		enum map_kind mk;
		if (parse_transform_item(p, &xf)) {
			*tex = texture_transform(*tex, &xf);
			continue;
		}
		if (t->kind == TOK_IDENT) {
			/* pigment, normal and finish identifiers replace those parts. */
			v = parse_ident_value(p);
			struct texture *tx = own_texture(tex);
			switch (v->kind) {
			case VAL_PIGMENT: pigment_unref(tx->pigment); tx->pigment = pigment_ref(v->pig); break;
			case VAL_NORMAL: normal_unref(tx->normal); tx->normal = normal_ref(v->nrm); break;
			case VAL_FINISH: tx->finish = *v->fin; break;
			case VAL_MAP:
				if (v->map->kind != MAP_TEXTURE)
					parse_wrong_kind(p, v, "a texture_map");
				if (tx->kind != TEX_PATTERNED || pattern_is_block(tx->pat.kind))
					parse_error(p, "a texture_map identifier needs a continuous pattern before it");
				set_map(p, &tx->map, blend_map_ref(v->map));
				break;
			default: parse_wrong_kind(p, v, "a texture, pigment, normal, finish or texture_map");
			}
			parse_advance(p);
			continue;
		}
		if (parse_at_pattern(p, &pk)) {
			struct texture *tx = own_texture(tex);
			blend_map_unref(tx->map);
			tx->map = NULL;
			tx->kind = TEX_PATTERNED;
			parse_pattern_type(p, &tx->pat, PATTERN_IN_TEXTURE);
			in_object = tx->pat.kind == PAT_OBJECT;
			continue;
		}
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a texture item or '}'");
		if (is_map_kw((enum kw)t->kw, &mk) && mk == MAP_TEXTURE) {
			struct texture *tx = own_texture(tex);
			if (tx->kind != TEX_PATTERNED)
				parse_error(p, "a texture_map needs a pattern before it");
			set_map(p, &tx->map, block_map(p, mk, &tx->pat));
			continue;
		}
		switch (t->kw) {
		case KW_PIGMENT: case KW_NORMAL: case KW_FINISH: {
			struct texture *tx = own_texture(tex);
			if (tx->kind != TEX_PLAIN)
				parse_error(p, "a patterned texture takes its %s from its textures, not directly", kw_names[t->kw]);
			if (t->kw == KW_PIGMENT)
				parse_pigment(p, &tx->pigment);
			else if (t->kw == KW_NORMAL)
				parse_normal(p, &tx->normal);
			else
				parse_finish(p, &tx->finish);
			continue;
		}
		case KW_TEXTURE: {
			struct texture *tx = own_texture(tex);
			if (tx->kind != TEX_PATTERNED || !pattern_is_block(tx->pat.kind))
				parse_error(p, "a texture inside a texture must be an entry of a block pattern's list (checker, hexagon, brick, ...)");
			list_room(p, tx->map, &tx->pat, "textures");
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			struct texture *item = read_texture(p, TOK_RBRACE);
			list_entry(&tx->map, MAP_TEXTURE, &tx->pat)->item = item;
			parse_accept(p, TOK_COMMA);
			continue;
		}
		case KW_TILES: {
			/* The old form of `checker texture {A} texture {B}`. */
			parse_advance(p);
			struct texture *tx = own_texture(tex);
			blend_map_unref(tx->map);
			pattern_clear(&tx->pat);
			tx->pat = pattern_make(PAT_CHECKER);
			tx->kind = TEX_PATTERNED;
			tx->map = blend_map_new(MAP_TEXTURE, 2);
			tx->map->n = 0;
			for (int i = 0; i < 2; i++) {
				if (i == 1 && !parse_accept_kw(p, KW_TILE2))
					parse_expected(p, "tile2");
				if (!parse_is_kw(p, KW_TEXTURE))
					parse_expected(p, "a texture");
				struct texture *item = read_layers(p, NULL, TOK_EOF);
				list_entry(&tx->map, MAP_TEXTURE, &tx->pat)->item = item;
			}
			continue;
		}
		case KW_MATERIAL_MAP: {
			struct texture *tx = own_texture(tex);
			blend_map_unref(tx->map);
			tx->map = NULL;
			pattern_clear(&tx->pat);
			tx->pat = pattern_make(PAT_IMAGE);
			tx->kind = TEX_MATERIAL;
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			parse_image_mapping(p, &tx->pat.img);
			int cap = 4;
			tx->map = blend_map_new(MAP_TEXTURE, cap);
			tx->map->n = 0;
			while (!parse_accept(p, TOK_RBRACE)) {
				if (parse_transform_item(p, &xf)) {
					pattern_transform(&tx->pat, &xf);
					continue;
				}
				if (!parse_is_kw(p, KW_TEXTURE))
					parse_expected(p, "a texture, a transformation or '}' in the material_map");
				if (tx->map->n >= MAP_MAX_ENTRIES)
					parse_error(p, "a material_map has at most %d textures", MAP_MAX_ENTRIES);
				if (tx->map->n == cap) {
					cap *= 2;
					tx->map->e = realloc(tx->map->e, (size_t)cap * sizeof *tx->map->e);
					if (!tx->map->e) abort();
				}
				struct map_entry *e = &tx->map->e[tx->map->n];
				memset(e, 0, sizeof *e);
				e->value = tx->map->n;
				parse_advance(p);
				parse_expect(p, TOK_LBRACE);
				e->item = read_texture(p, TOK_RBRACE);
				tx->map->n++;
			}
			if (tx->map->n == 0)
				parse_error(p, "a material_map needs at least one texture");
			continue;
		}
		default:
			break;
		}
		late_uv_mapping(p, "texture");
		if ((*tex)->kind != TEX_PLAIN && parse_pattern_modifier(p, &own_texture(tex)->pat))
			continue;
		parse_expected(p, "pigment, normal, finish, a pattern, a transformation or '}'");
	}
	struct texture *tx = *tex;
	if (tx->kind == TEX_PATTERNED && tx->map && pattern_is_block(tx->pat.kind) &&
	    tx->map->n < pattern_block_entries(tx->pat.kind))
		finish_list(p, own_texture(tex)->map, &tx->pat);
	if (uv)
		texture_uv_mapping(tex, true);
}

/* A copy of the layers of top (each layer copied) with under below the
 * last one. Takes the reference to top and to under. */
struct texture *parse_layer_onto(struct texture *top, struct texture *under)
{
	if (!under)
		return top;
	struct texture *c = own_texture(&top);
	struct texture *cur = c;
	while (cur->next) {
		struct texture *n = cur->next;
		if (n->refs > 1) {
			cur->next = texture_copy(n);
			texture_unref(n);
		}
		cur = cur->next;
	}
	cur->next = under;
	return c;
}

static struct texture *read_layers(struct parser *p, struct texture *under, enum tok_kind end)
{
	struct texture **h = holder_new(sizeof *h);
	*h = under;
	int slot = parse_own(p, h, parse_free_texture_holder);
	do {
		parse_advance(p); /* texture */
		parse_expect(p, TOK_LBRACE);
		struct texture *t = read_texture(p, TOK_RBRACE);
		*h = parse_layer_onto(t, *h);
	} while (end != TOK_EOF ? parse_is_kw(p, KW_TEXTURE) : false);
	if (end != TOK_EOF)
		parse_expect(p, end);
	struct texture *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

struct texture *parse_private_texture(struct parser *p, struct texture **tex)
{
	if (*tex && texture_is_patterned(*tex))
		parse_error(p, "cannot layer a %s over a patterned texture", kw_names[parse_peek(p)->kw]);
	if (!*tex)
		*tex = default_texture(p);
	else
		own_texture(tex);
	return *tex;
}

/* texture := texture '{' texture_body '}'
 * Replaces *tex. */
void parse_texture(struct parser *p, struct texture **tex)
{
	parse_advance(p); /* texture */
	parse_expect(p, TOK_LBRACE);
	texture_body(p, tex, TOK_RBRACE);
}

/* layered_texture := texture { texture }: a texture statement layered on
 * top of what *tex holds (NULL: nothing yet), as several texture
 * statements on one object are in POV-Ray. */
void parse_texture_layer(struct parser *p, struct texture **tex)
{
	if (*tex && texture_is_patterned(*tex))
		parse_error(p, "cannot layer a texture over a patterned texture");
	struct srcpos at = parse_peek(p)->pos;
	struct texture *t = NULL;
	struct texture **h = holder_new(sizeof *h);
	int slot = parse_own(p, h, parse_free_texture_holder);
	parse_texture(p, h);
	t = *h;
	if (*tex && texture_is_patterned(t))
		parse_error_at(p, at, "cannot layer a patterned texture over another texture");
	*h = NULL;
	parse_release(p, slot);
	free(h);
	*tex = parse_layer_onto(t, *tex);
}

/* A pigment or normal value for #declare: the statement read into a
 * fresh holder. The caller owns the result. */
struct pigment *parse_pigment_value(struct parser *p)
{
	struct pigment **h = holder_new(sizeof *h);
	*h = pigment_new();
	int slot = parse_own(p, h, free_pigment_holder);
	parse_pigment(p, h);
	struct pigment *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

struct normal *parse_normal_value(struct parser *p)
{
	struct normal **h = holder_new(sizeof *h);
	int slot = parse_own(p, h, free_normal_holder);
	parse_normal(p, h);
	struct normal *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

/* A texture value for #declare: texture { } { texture { } } (layered when
 * several follow). The caller owns the result. */
struct texture *parse_texture_value(struct parser *p)
{
	struct texture **h = holder_new(sizeof *h);
	int slot = parse_own(p, h, parse_free_texture_holder);
	/* The next token is looked at raw: a macro call after the
	 * declaration (which may use the name being declared) must not run
	 * before the declaration is complete. */
	const struct token *t;
	do {
		parse_texture_layer(p, h);
		t = parse_peek_raw(p);
	} while (t && t->kind == TOK_KEYWORD && t->kw == KW_TEXTURE);
	struct texture *r = *h;
	*h = NULL;
	parse_release(p, slot);
	free(h);
	return r;
}

/* ---- material ---- */

/* material := material '{' [IDENT] { texture | interior | transformation } '}'
 * Fills *m (tex and interior: references, replaced). Transformations move
 * the textures read so far, as on an object. */
void parse_material(struct parser *p, struct material *m)
{
	parse_advance(p); /* material */
	parse_expect(p, TOK_LBRACE);
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_MATERIAL)
			parse_wrong_kind(p, v, "a material");
		texture_unref(m->tex);
		interior_unref(m->interior);
		m->tex = texture_ref(v->mat->tex);
		m->interior = interior_ref(v->mat->interior);
		parse_advance(p);
	}
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform xf;
		if (parse_transform_item(p, &xf)) {
			if (m->tex)
				m->tex = texture_transform(m->tex, &xf);
			continue;
		}
		if (parse_is_kw(p, KW_TEXTURE))
			parse_texture_layer(p, &m->tex);
		else if (parse_is_kw(p, KW_INTERIOR))
			parse_interior(p, &m->interior);
		else
			parse_expected(p, "texture, interior, a transformation or '}' in the material");
	}
}

/* ---- #default ---- */

/* #default '{' { texture | pigment | normal | finish } '}' : what objects
 * without their own get from now on. */
void parse_default(struct parser *p)
{
	parse_expect(p, TOK_LBRACE);
	while (!parse_accept(p, TOK_RBRACE)) {
		/* Each part is read into a value of its own and set as the default
		 * only once it is whole: a #default among its tokens changes the
		 * default texture, and may free it, while it is read (fuzz run 19:
		 * a leak, and then uses after free). The part starts from the
		 * defaults as they are when its first token is read, as in POV-Ray
		 * (measured: `#default { texture { #default { pigment { Red } } } }`
		 * leaves the default red). */
		if (parse_is_kw(p, KW_TEXTURE)) {
			struct srcpos at = parse_peek(p)->pos;
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			struct texture *t = read_texture(p, TOK_RBRACE);
			if (texture_is_patterned(t)) {
				texture_unref(t);
				parse_error_at(p, at, "a #default texture cannot be patterned (a texture_map, or a block "
				               "pattern of textures), as in POV-Ray");
			}
			texture_unref(p->default_tex);
			p->default_tex = t;
		} else if (parse_is_kw(p, KW_FINISH)) {
			struct finish f = parse_private_texture(p, &p->default_tex)->finish;
			parse_finish(p, &f);
			parse_private_texture(p, &p->default_tex)->finish = f;
		} else if (parse_is_kw(p, KW_PIGMENT) || parse_is_kw(p, KW_NORMAL)) {
			bool pig = parse_is_kw(p, KW_PIGMENT);
			parse_advance(p);
			parse_expect(p, TOK_LBRACE);
			const struct texture *d = p->default_tex;
			if (pig) {
				struct pigment *pg = read_pigment(p, d ? d->pigment : NULL, TOK_RBRACE);
				struct texture *t = parse_private_texture(p, &p->default_tex);
				pigment_unref(t->pigment);
				t->pigment = pg;
			} else {
				struct normal *n = read_normal(p, d ? d->normal : NULL, TOK_RBRACE);
				struct texture *t = parse_private_texture(p, &p->default_tex);
				normal_unref(t->normal);
				t->normal = n;
			}
		} else {
			parse_expected(p, "texture, pigment, normal, finish or '}' in #default");
		}
	}
}

/* texture_parse.c: pigments, normals, textures, maps, materials and
 * #default. Each grammar function names its production above it. */
#include "lang/parser.h"

#include <stdlib.h>
#include <string.h>

/* ---- textures ---- */

/* pigment := pigment '{' [IDENT] [color] '}' */
void parse_pigment(struct parser *p, struct pigment **pig)
{
	parse_advance(p); /* pigment */
	parse_expect(p, TOK_LBRACE);
	const struct value *v = parse_ident_value(p);
	if (v && v->kind == VAL_PIGMENT) {
		pigment_unref(*pig);
		*pig = pigment_ref(v->pig);
		parse_advance(p);
	}
	while (!parse_is(p, TOK_RBRACE)) {
		if (parse_starts_expression(p)) {
			struct rgbft c = parse_color(p);
			pigment_unref(*pig);
			*pig = pigment_new();
			(*pig)->color = c;
			continue;
		}
		struct xform t;
		if (parse_transform_item(p, &t))
			continue; /* a solid colour is the same everywhere */
		parse_expected(p, "a color or a pigment modifier");
	}
	parse_advance(p);
}

struct texture *parse_private_texture(struct parser *p, struct texture **tex)
{
	if (!*tex)
		*tex = p->default_tex ? texture_copy(p->default_tex) : texture_new();
	else if ((*tex)->refs > 1) {
		struct texture *c = texture_copy(*tex);
		texture_unref(*tex);
		*tex = c;
	}
	return *tex;
}

/* texture := texture '{' [IDENT] { pigment | finish | transform } '}'
 * Reads into *tex (created or made private as needed). */
void parse_texture(struct parser *p, struct texture **tex)
{
	parse_advance(p); /* texture */
	parse_expect(p, TOK_LBRACE);
	const struct value *v = parse_ident_value(p);
	if (v) {
		if (v->kind != VAL_TEXTURE)
			parse_wrong_kind(p, v, "a texture");
		texture_unref(*tex);
		*tex = texture_ref(v->tex);
		parse_advance(p);
	} else {
		/* A texture statement starts from the defaults, not from what the
		 * object had. */
		texture_unref(*tex);
		*tex = p->default_tex ? texture_copy(p->default_tex) : texture_new();
	}
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		if (parse_is_kw(p, KW_PIGMENT))
			parse_pigment(p, &parse_private_texture(p, tex)->pigment);
		else if (parse_is_kw(p, KW_FINISH))
			parse_finish(p, &parse_private_texture(p, tex)->finish);
		else if (!parse_transform_item(p, &t))
			parse_expected(p, "pigment, finish, a transformation or '}'");
	}
}

/* ---- #default ---- */

/* #default '{' { texture | pigment | finish } '}' : what objects without
 * their own get from now on. */
void parse_default(struct parser *p)
{
	parse_expect(p, TOK_LBRACE);
	while (!parse_accept(p, TOK_RBRACE)) {
		if (parse_is_kw(p, KW_TEXTURE))
			parse_texture(p, &p->default_tex);
		else if (parse_is_kw(p, KW_PIGMENT))
			parse_pigment(p, &parse_private_texture(p, &p->default_tex)->pigment);
		else if (parse_is_kw(p, KW_FINISH))
			parse_finish(p, &parse_private_texture(p, &p->default_tex)->finish);
		else
			parse_expected(p, "texture, pigment, finish or '}' in #default");
	}
}


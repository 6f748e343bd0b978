/* objects3.c: the arguments and own modifiers of blob, with POV-Ray's
 * rules (measured where the manual is silent: the components and the
 * threshold come before the object modifiers; commas are optional; a
 * component's texture, pigment, normal and finish, and its
 * transformations, are the only modifiers it takes). The shape is in
 * src/geom/blob.c. */
#include "geom/blob.h"
#include "lang/parser.h"

#include <math.h>
#include <stdlib.h>

static void opt_comma(struct parser *p)
{
	parse_accept(p, TOK_COMMA);
}

static void free_object_cb(void *o)
{
	object_free(o);
}

/* Is the transformation at the current token one a sphere component takes
 * into its centre and radius (translate, rotate, a uniform scale)? Reads
 * it into *t; false with nothing read if there is none (*is_xf). */
static bool read_component_transform(struct parser *p, struct xform *t, bool *rigid)
{
	const struct token *tk = parse_peek(p);
	enum kw k = tk->kind == TOK_KEYWORD ? (enum kw)tk->kw : KW_OBJECT;
	if (!parse_transform_item(p, t))
		return false;
	*rigid = k == KW_TRANSLATE || k == KW_ROTATE;
	if (k == KW_SCALE)
		*rigid = t->fwd.m[0][0] == t->fwd.m[1][1] && t->fwd.m[1][1] == t->fwd.m[2][2];
	return true;
}

/* component_modifier := texture | pigment | normal | finish | transformation
 * Reads them up to the component's '}'. */
static void component_modifiers(struct parser *p, struct object *o, int ci)
{
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		bool rigid;
		if (read_component_transform(p, &t, &rigid)) {
			blob_transform_component(o, ci, &t, rigid);
			continue;
		}
		struct texture **tex = blob_component_texture(o, ci);
		if (parse_is_kw(p, KW_TEXTURE))
			parse_texture_layer(p, tex);
		else if (parse_is_kw(p, KW_PIGMENT))
			parse_pigment(p, &parse_private_texture(p, tex)->pigment);
		else if (parse_is_kw(p, KW_NORMAL))
			parse_normal(p, &parse_private_texture(p, tex)->normal);
		else if (parse_is_kw(p, KW_FINISH))
			parse_finish(p, &parse_private_texture(p, tex)->finish);
		else
			parse_expected(p, "a texture, pigment, normal, finish, transformation or '}' (a blob component "
			               "takes no other modifier)");
	}
}

/* blob '{' { blob_item } ...
 * blob_item := sphere '{' V ',' F ',' [strength] F { component_modifier } '}'
 *            | cylinder '{' V ',' V ',' F ',' [strength] F { component_modifier } '}'
 *            | component F ',' F ',' V
 *            | threshold F */
static struct object *parse_blob(struct parser *p, struct srcpos at)
{
	struct object *o = blob_new(at);
	int slot = parse_own(p, o, free_object_cb);
	for (;;) {
		struct srcpos iat = parse_peek(p)->pos;
		if (parse_accept_kw(p, KW_THRESHOLD)) {
			blob_set_threshold(o, parse_float(p));
		} else if (parse_accept_kw(p, KW_COMPONENT)) {
			double s = parse_float(p);
			opt_comma(p);
			double r = parse_float(p);
			opt_comma(p);
			vec3 c = parse_vector(p);
			blob_add_sphere(o, c, r, s);
		} else if (parse_accept_kw(p, KW_SPHERE)) {
			parse_expect(p, TOK_LBRACE);
			vec3 c = parse_vector(p);
			opt_comma(p);
			double r = parse_float(p);
			opt_comma(p);
			parse_accept_kw(p, KW_STRENGTH);
			double s = parse_float(p);
			component_modifiers(p, o, blob_add_sphere(o, c, r, s));
		} else if (parse_accept_kw(p, KW_CYLINDER)) {
			parse_expect(p, TOK_LBRACE);
			vec3 a = parse_vector(p);
			opt_comma(p);
			vec3 b = parse_vector(p);
			opt_comma(p);
			double r = parse_float(p);
			opt_comma(p);
			parse_accept_kw(p, KW_STRENGTH);
			double s = parse_float(p);
			int ci = blob_add_cylinder(o, a, b, r, s);
			if (ci < 0)
				parse_error_at(p, iat, "a blob's cylinder component needs two different ends (POV-Ray: "
				               "degenerate cylindrical component)");
			component_modifiers(p, o, ci);
		} else {
			break;
		}
	}
	if (blob_component_count(o) == 0)
		parse_error_at(p, at, "a blob needs at least one component (sphere, cylinder or component)");
	parse_release(p, slot);
	return o;
}

bool parse_is_object3(enum kw k)
{
	return k == KW_BLOB;
}

struct object *parse_object3(struct parser *p, enum kw k, struct srcpos at)
{
	(void)k;
	return parse_blob(p, at);
}

/* An optional boolean after a flag keyword (on when absent). */
static bool flag_value(struct parser *p)
{
	return parse_starts_expression(p) ? parse_float(p) != 0 : true;
}

bool parse_object3_modifier(struct parser *p, struct object *o, enum kw k)
{
	if (k != KW_BLOB)
		return false;
	if (parse_accept_kw(p, KW_STURM)) {
		blob_set_sturm(o, flag_value(p));
		return true;
	}
	if (parse_accept_kw(p, KW_HIERARCHY)) {
		blob_set_hierarchy(o, flag_value(p));
		return true;
	}
	return false;
}

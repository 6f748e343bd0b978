/* objects.c: the object statements: every primitive, CSG, object
 * references and the modifiers they share, and the transformations (which
 * textures use too). Each grammar function names its production above it.
 * The parser only calls the builder API (src/geom/shapes.h, csg.h,
 * mesh.h); it knows nothing of how shapes are intersected. */
#include "lang/parser.h"

#include "geom/csg.h"
#include "geom/mesh.h"
#include "geom/shapes.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

/* POV-Ray's poly orders. */
enum { POLY_MIN_ORDER = 2, POLY_MAX_ORDER = 7 };

static void free_object_cb(void *o) { object_free(o); }

static void free_material_holder(void *h)
{
	struct material *m = h;
	texture_unref(m->tex);
	interior_unref(m->interior);
	free(m);
}

/* ---- transformations ---- */

/* A transform identifier at the current token, consumed. */
static struct xform transform_ident(struct parser *p)
{
	const struct value *v = parse_ident_value(p);
	if (!v)
		parse_expected(p, "a transform identifier");
	if (v->kind != VAL_TRANSFORM)
		parse_wrong_kind(p, v, "a transform");
	struct xform t = *v->xf;
	parse_advance(p);
	return t;
}

/* transform_block := '{' { IDENT | transform_item | inverse } '}'
 * `inverse` inverts the whole block, wherever it stands (POV-Ray 3.7). */
static struct xform parse_transform_block(struct parser *p)
{
	parse_expect(p, TOK_LBRACE);
	struct xform acc = xform_identity();
	bool inverse = false;
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		if (parse_is(p, TOK_IDENT))
			t = transform_ident(p);
		else if (parse_accept_kw(p, KW_INVERSE)) {
			inverse = true;
			continue;
		} else if (!parse_transform_item(p, &t))
			parse_expected(p, "a transformation, a transform identifier, inverse or '}'");
		acc = xform_compose(&t, &acc);
	}
	return inverse ? xform_invert(&acc) : acc;
}

/* transform_item := translate VECTOR | rotate VECTOR | scale VECTOR
 *                 | matrix < 12 floats > | transform IDENT
 *                 | transform transform_block */
bool parse_transform_item(struct parser *p, struct xform *out)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	struct srcpos at = t->pos;
	switch (t->kw) {
	case KW_TRANSLATE:
		parse_advance(p);
		*out = xform_translate(parse_vector(p));
		return true;
	case KW_ROTATE:
		parse_advance(p);
		*out = xform_rotate(parse_vector(p));
		return true;
	case KW_SCALE: {
		parse_advance(p);
		vec3 s = parse_vector(p);
		/* POV-Ray turns a zero scale factor into 1, with a warning. */
		double *c[3] = {&s.x, &s.y, &s.z};
		for (int i = 0; i < 3; i++)
			if (*c[i] == 0) {
				parse_warning_at(p, at, "scale by 0 changed to scale by 1");
				*c[i] = 1;
			}
		*out = xform_scale(s);
		return true;
	}
	case KW_MATRIX: {
		parse_advance(p);
		double m[12];
		int got = parse_number_list(p, m, 12);
		if (got != 12)
			parse_error_at(p, at, "a matrix needs exactly 12 numbers, found %d", got);
		/* POV-Ray turns an all-zero column of the 3x3 part into the
		 * identity's, with a warning, as it does a scale by 0. */
		for (int c = 0; c < 3; c++)
			if (m[c] == 0 && m[3 + c] == 0 && m[6 + c] == 0) {
				parse_warning_at(p, at, "matrix column %d is all 0: changed to the identity's", c + 1);
				m[4 * c] = 1;
			}
		*out = xform_matrix(m);
		if (mat_is_identity(&out->inv) && !mat_is_identity(&out->fwd))
			parse_error_at(p, at, "this matrix cannot be inverted (it flattens space)");
		return true;
	}
	case KW_TRANSFORM:
		parse_advance(p);
		*out = parse_is(p, TOK_LBRACE) ? parse_transform_block(p) : transform_ident(p);
		return true;
	default:
		return false;
	}
}

/* transform '{' transform_block '}' as a value (after the keyword is
 * seen; the caller owns the result). */
struct xform *parse_transform_value(struct parser *p)
{
	parse_advance(p); /* transform */
	struct xform *t = malloc(sizeof *t);
	if (!t) abort();
	int slot = parse_own(p, t, free);
	*t = parse_is(p, TOK_LBRACE) ? parse_transform_block(p) : transform_ident(p);
	parse_release(p, slot);
	return t;
}

/* ---- primitives ---- */

/* What a primitive statement said before its modifiers, kept so the
 * primitive can be built again when `open` or `sturm` follows. */
struct shape_args {
	enum kw kw;
	vec3 v[6];
	double f[4];
	int order;
	bool open, sturm;
	double coef[120];            /* last: only a polynomial writes and reads it (its
	                              * exact count), so the rest is cleared alone */
};

/* The comma between arguments: optional, as in POV-Ray
 * (`sphere { <0,0,0> 1 }` is a sphere). */
static void opt_comma(struct parser *p)
{
	parse_accept(p, TOK_COMMA);
}

static int poly_coef_count(int order)
{
	return (order + 1) * (order + 2) * (order + 3) / 6;
}

/* Build the primitive a holds. */
static struct object *build_shape(const struct shape_args *a, struct srcpos at)
{
	switch (a->kw) {
	case KW_SPHERE: return sphere_new(a->v[0], a->f[0], at);
	case KW_PLANE: return plane_new(a->v[0], a->f[0], at);
	case KW_BOX: return box_new(a->v[0], a->v[1], at);
	case KW_CYLINDER: return cylinder_new(a->v[0], a->v[1], a->f[0], a->open, at);
	case KW_CONE: return cone_new(a->v[0], a->f[0], a->v[1], a->f[1], a->open, at);
	case KW_DISC: return disc_new(a->v[0], a->v[1], a->f[0], a->f[1], at);
	case KW_TORUS: return torus_new(a->f[0], a->f[1], a->sturm, at);
	case KW_TRIANGLE: return triangle_new(a->v[0], a->v[1], a->v[2], at);
	case KW_SMOOTH_TRIANGLE:
		return smooth_triangle_new(a->v[0], a->v[1], a->v[2], a->v[3], a->v[4], a->v[5], at);
	case KW_QUADRIC: return quadric_new(a->v[0], a->v[1], a->v[2], a->f[0], at);
	case KW_CUBIC:
	case KW_QUARTIC:
	case KW_POLY: return poly_new(a->order, a->coef, a->sturm, at);
	case KW_SUPERELLIPSOID: return superellipsoid_new(a->f[0], a->f[1], at);
	default: return NULL;
	}
}

/* A vector that must not be zero (a direction or normal). */
static vec3 nonzero_vector(struct parser *p, const char *what)
{
	struct srcpos at = parse_peek(p)->pos;
	vec3 v = parse_vector(p);
	if (v.x == 0 && v.y == 0 && v.z == 0)
		parse_error_at(p, at, "%s cannot be the zero vector", what);
	return v;
}

/* The polynomial's coefficients: '<' exactly n floats '>'. */
static void poly_coefs(struct parser *p, struct shape_args *a, const char *name)
{
	struct srcpos at = parse_peek(p)->pos;
	int n = poly_coef_count(a->order);
	int got = parse_number_list(p, a->coef, n);
	if (got != n)
		parse_error_at(p, at, "%s of order %d needs %d coefficients, found %d", name, a->order, n, got);
}

/* The primitive's own arguments, after its '{'. */
static void parse_shape_args(struct parser *p, struct shape_args *a)
{
	switch (a->kw) {
	case KW_SPHERE: /* sphere '{' VECTOR ',' FLOAT */
		a->v[0] = parse_vector(p);
		opt_comma(p);
		a->f[0] = parse_float(p);
		break;
	case KW_PLANE: /* plane '{' VECTOR ',' FLOAT */
		a->v[0] = nonzero_vector(p, "a plane's normal");
		opt_comma(p);
		a->f[0] = parse_float(p);
		break;
	case KW_BOX: /* box '{' VECTOR ',' VECTOR */
		a->v[0] = parse_vector(p);
		opt_comma(p);
		a->v[1] = parse_vector(p);
		break;
	case KW_CYLINDER: { /* cylinder '{' VECTOR ',' VECTOR ',' FLOAT */
		a->v[0] = parse_vector(p);
		opt_comma(p);
		struct srcpos cat = parse_peek(p)->pos;
		a->v[1] = parse_vector(p);
		if (v3_len(v3_sub(a->v[1], a->v[0])) == 0)
			parse_error_at(p, cat, "a cylinder's cap is at its base (a degenerate cylinder)");
		opt_comma(p);
		a->f[0] = parse_float(p);
		break;
	}
	case KW_CONE: { /* cone '{' VECTOR ',' FLOAT ',' VECTOR ',' FLOAT */
		a->v[0] = parse_vector(p);
		opt_comma(p);
		a->f[0] = parse_float(p);
		opt_comma(p);
		struct srcpos cat = parse_peek(p)->pos;
		a->v[1] = parse_vector(p);
		if (v3_len(v3_sub(a->v[1], a->v[0])) == 0)
			parse_error_at(p, cat, "a cone's cap is at its base (a degenerate cone)");
		opt_comma(p);
		a->f[1] = parse_float(p);
		break;
	}
	case KW_DISC: /* disc '{' VECTOR ',' VECTOR ',' FLOAT [',' FLOAT] */
		a->v[0] = parse_vector(p);
		opt_comma(p);
		a->v[1] = parse_vector(p); /* POV-Ray accepts a zero normal */
		opt_comma(p);
		a->f[0] = parse_float(p);
		a->f[1] = 0;
		if (parse_accept(p, TOK_COMMA))
			a->f[1] = parse_float(p);
		break;
	case KW_TORUS: /* torus '{' FLOAT ',' FLOAT */
		a->f[0] = parse_float(p);
		opt_comma(p);
		a->f[1] = parse_float(p);
		break;
	case KW_TRIANGLE: /* triangle '{' VECTOR ',' VECTOR ',' VECTOR */
		for (int i = 0; i < 3; i++) {
			if (i)
				opt_comma(p);
			a->v[i] = parse_vector(p);
		}
		break;
	case KW_SMOOTH_TRIANGLE: /* smooth_triangle '{' 6 VECTORs, comma-separated */
		for (int i = 0; i < 6; i++) {
			if (i)
				opt_comma(p);
			a->v[i] = parse_vector(p);
		}
		break;
	case KW_QUADRIC: /* quadric '{' VECTOR ',' VECTOR ',' VECTOR ',' FLOAT */
		for (int i = 0; i < 3; i++) {
			a->v[i] = parse_vector(p);
			opt_comma(p);
		}
		a->f[0] = parse_float(p);
		break;
	case KW_CUBIC: /* cubic '{' < 20 floats > */
		a->order = 3;
		poly_coefs(p, a, "a cubic");
		break;
	case KW_QUARTIC: /* quartic '{' < 35 floats > */
		a->order = 4;
		poly_coefs(p, a, "a quartic");
		break;
	case KW_POLY: { /* poly '{' INT ',' < floats > */
		struct srcpos at = parse_peek(p)->pos;
		/* POV-Ray truncates a fractional order. */
		double o = trunc(parse_float(p));
		if (!(o >= POLY_MIN_ORDER && o <= POLY_MAX_ORDER))
			parse_error_at(p, at, "a poly's order must be from %d to %d, found %g", POLY_MIN_ORDER,
			               POLY_MAX_ORDER, o);
		a->order = (int)o;
		opt_comma(p);
		poly_coefs(p, a, "a poly");
		break;
	}
	case KW_SUPERELLIPSOID: { /* superellipsoid '{' VECTOR (e, n) */
		struct srcpos at = parse_peek(p)->pos;
		struct value v = parse_expression(p);
		if (v.kind != VAL_VECTOR && v.kind != VAL_FLOAT)
			parse_error_at(p, at, "a superellipsoid needs a vector <e, n>, found a %s", val_kind_name(v.kind));
		/* A float is promoted to <f, f>; exponents of 0 or less are
		 * accepted, as by POV-Ray (the shape raises them to 0.001). */
		a->f[0] = v.v[0];
		a->f[1] = v.kind == VAL_FLOAT ? v.v[0] : v.v[1];
		break;
	}
	default:
		break;
	}
}

/* ---- meshes ---- */

/* Mesh lists are indexed in 32 bits. */
#define MESH_MAX_ITEMS 0x7fffffffu

/* count := FLOAT, a non-negative whole number, before a mesh2 list. */
static size_t list_count(struct parser *p, const char *what)
{
	struct srcpos at = parse_peek(p)->pos;
	double n = trunc(parse_float(p)); /* POV-Ray truncates fractions */
	if (!(n >= 0 && n <= MESH_MAX_ITEMS))
		parse_error_at(p, at, "the number of %s must be from 0 to %u, found %g", what, MESH_MAX_ITEMS, n);
	if (n > (double)p->lim.mesh_size)
		parse_error_at(p, at, "%.0f %s is more than a mesh may have (%zu; lucent --limit mesh-size=N raises it)", n,
		               what, p->lim.mesh_size);
	return (size_t)n;
}

/* An index into a list of n entries (a fraction truncated, as by POV-Ray). */
static uint32_t list_index(struct parser *p, double v, size_t n, const char *what, struct srcpos at)
{
	v = trunc(v);
	if (!(v >= 0 && v < (double)n))
		parse_error_at(p, at, "%s index %g is out of range (the list has %zu %s)", what, v, n,
		               n == 1 ? "entry" : "entries");
	return (uint32_t)v;
}

static void free_mesh_builder_cb(void *b) { mesh_builder_free(b); }

/* A texture for a mesh: texture '{' ... '}', added to the builder's list. */
static uint32_t mesh_texture(struct parser *p, struct mesh_builder *mb)
{
	struct texture **holder = calloc(1, sizeof *holder);
	if (!holder) abort();
	int slot = parse_own(p, holder, parse_free_texture_holder);
	parse_texture(p, holder);
	uint32_t i = mesh_add_texture(mb, *holder);
	parse_release(p, slot);
	parse_free_texture_holder(holder);
	return i;
}

/* A uv vector: a 2-component vector (a float is promoted). */
static void uv_value(struct parser *p, double uv[2])
{
	struct srcpos at = parse_peek(p)->pos;
	struct value v = parse_expression(p);
	if (v.kind != VAL_VECTOR && v.kind != VAL_FLOAT)
		parse_error_at(p, at, "expected a 2-component uv vector, found a %s", val_kind_name(v.kind));
	uv[0] = v.v[0];
	uv[1] = v.kind == VAL_FLOAT ? v.v[0] : v.v[1];
}

/* mesh_item := (triangle | smooth_triangle) '{' vectors
 *              [uv_vectors UV UV UV] [texture '{' ... '}'] '}'
 *            | inside_vector VECTOR | hierarchy [BOOL] */
static bool parse_mesh_item(struct parser *p, struct mesh_builder *mb)
{
	if (parse_is_kw(p, KW_TRIANGLE) || parse_is_kw(p, KW_SMOOTH_TRIANGLE)) {
		if (mesh_face_count(mb) >= p->lim.mesh_size)
			parse_error(p, "the mesh has more than %zu triangles (lucent --limit mesh-size=N raises the limit)",
			            p->lim.mesh_size);
		bool smooth = parse_is_kw(p, KW_SMOOTH_TRIANGLE);
		parse_advance(p);
		parse_expect(p, TOK_LBRACE);
		uint32_t v[3], n[3], uv[3], tex[3] = {0, 0, 0};
		for (int i = 0; i < 3; i++) {
			if (i)
				opt_comma(p);
			v[i] = mesh_add_vertex(mb, parse_vector(p));
			if (smooth) {
				opt_comma(p);
				n[i] = mesh_add_normal(mb, parse_vector(p));
			}
		}
		bool has_uv = false;
		int ntex = 0;
		for (;;) {
			if (parse_accept_kw(p, KW_UV_VECTORS)) {
				for (int i = 0; i < 3; i++) {
					double c[2];
					if (i)
						opt_comma(p);
					uv_value(p, c);
					uv[i] = mesh_add_uv(mb, c[0], c[1]);
				}
				has_uv = true;
			} else if (parse_is_kw(p, KW_TEXTURE)) {
				tex[0] = mesh_texture(p, mb);
				ntex = 1;
			} else {
				break;
			}
		}
		parse_expect(p, TOK_RBRACE);
		mesh_add_face(mb, v, ntex, tex);
		uint32_t f = mesh_face_count(mb) - 1;
		if (smooth)
			mesh_set_face_normals(mb, f, n);
		if (has_uv)
			mesh_set_face_uvs(mb, f, uv);
		return true;
	}
	if (parse_accept_kw(p, KW_INSIDE_VECTOR)) {
		mesh_set_inside_vector(mb, parse_vector(p));
		return true;
	}
	if (parse_accept_kw(p, KW_HIERARCHY)) {
		/* lucent always builds the mesh's hierarchy; the switch is read
		 * for compatibility. */
		if (parse_starts_expression(p))
			(void)parse_float(p);
		return true;
	}
	return false;
}

/* The lists of mesh2, in the order POV-Ray requires them. */
enum mesh2_list { M2_VERTICES, M2_NORMALS, M2_UVS, M2_TEXTURES, M2_FACES, M2_NORMAL_INDICES, M2_UV_INDICES };
static const char *const m2_names[] = {"vertex_vectors", "normal_vectors", "uv_vectors", "texture_list",
                                       "face_indices", "normal_indices", "uv_indices"};
static const char *const m2_items[] = {"vertices", "normals", "uv vectors", "textures",
                                       "faces", "normal indices", "uv indices"};

/* The face in progress while face_indices is read: its texture indices
 * follow its vector. */
struct pending_face {
	bool set;
	uint32_t v[3], tex[3];
	int ntex;
	struct srcpos at;
};

static void flush_face(struct parser *p, struct mesh_builder *mb, struct pending_face *f)
{
	if (!f->set)
		return;
	if (f->ntex == 2)
		parse_error_at(p, f->at, "a face has 1 or 3 texture indices, not 2");
	mesh_add_face(mb, f->v, f->ntex, f->tex);
	f->set = false;
}

/* Reading one mesh2 list. */
struct list_state {
	enum mesh2_list which;
	size_t n, i;              /* entries announced, read */
	struct srcpos at;         /* the count, for messages about the whole list */
	struct pending_face face;
};

/* One vector item c[0..dim) of the list at vat. */
static void list_vector(struct parser *p, struct mesh_builder *mb, struct list_state *st, const double *c, int dim,
                        struct srcpos vat)
{
	enum mesh2_list which = st->which;
	double pad[3] = {c[0], dim > 1 ? c[1] : 0, dim > 2 ? c[2] : 0}; /* POV-Ray pads with 0 */
	c = pad;
	if (st->i == st->n)
		parse_error_at(p, vat, "%s has more entries than its count (%zu)", m2_names[which], st->n);
	uint32_t idx[3];
	if (which >= M2_FACES) {
		size_t lim = which == M2_FACES ? mesh_vertex_count(mb)
		             : which == M2_NORMAL_INDICES ? mesh_normal_count(mb) : mesh_uv_count(mb);
		const char *name = which == M2_FACES ? "vertex" : which == M2_NORMAL_INDICES ? "normal" : "uv";
		for (int k = 0; k < 3; k++)
			idx[k] = list_index(p, c[k], lim, name, vat);
	}
	switch (which) {
	case M2_VERTICES: mesh_add_vertex(mb, v3(c[0], c[1], c[2])); break;
	case M2_NORMALS: mesh_add_normal(mb, v3(c[0], c[1], c[2])); break;
	case M2_UVS: mesh_add_uv(mb, c[0], c[1]); break;
	case M2_FACES:
		flush_face(p, mb, &st->face);
		memcpy(st->face.v, idx, sizeof idx);
		st->face.ntex = 0;
		st->face.at = vat;
		st->face.set = true;
		break;
	case M2_NORMAL_INDICES: mesh_set_face_normals(mb, (uint32_t)st->i, idx); break;
	case M2_UV_INDICES: mesh_set_face_uvs(mb, (uint32_t)st->i, idx); break;
	default: break;
	}
	st->i++;
}

/* list '{' count [','] item { [','] item } '}', as POV-Ray reads mesh2's
 * lists (commas optional). face_indices items are <a,b,c> followed by 0, 1
 * or 3 texture indices when a texture_list was given. Runs of literal
 * vectors come from the lexer as one TOK_NUMLIST token. */
static void parse_mesh2_list(struct parser *p, struct mesh_builder *mb, enum mesh2_list which)
{
	parse_expect(p, TOK_LBRACE);
	struct list_state st = {.which = which, .at = parse_peek(p)->pos};
	st.n = list_count(p, m2_items[which]);
	size_t nfaces = mesh_face_count(mb);
	/* The first n faces get normals or uv vectors; the rest stay flat. */
	if ((which == M2_NORMAL_INDICES || which == M2_UV_INDICES) && st.n > nfaces)
		parse_error_at(p, st.at, "%s has %zu entries but there %s only %zu %s", m2_names[which], st.n,
		               nfaces == 1 ? "is" : "are", nfaces, nfaces == 1 ? "face" : "faces");
	for (;;) {
		opt_comma(p);
		const struct token *t = parse_peek(p);
		if (t->kind == TOK_RBRACE)
			break;
		struct srcpos vat = t->pos;
		if (t->kind == TOK_NUMLIST && which != M2_TEXTURES) {
			const struct numlist *l = t->list;
			struct numlist_iter it;
			lex_numlist_begin(&it, p->sm, vat.file, l);
			for (uint32_t k = 0; k < l->count; k++) {
				double c[3];
				struct srcpos kat;
				lex_numlist_next(&it, c, &kat);
				list_vector(p, mb, &st, c, (int)l->dim, kat);
			}
			parse_advance(p);
			continue;
		}
		if (which == M2_TEXTURES) {
			if (!parse_is_kw(p, KW_TEXTURE))
				parse_expected(p, "a texture or '}'");
			if (st.i == st.n)
				parse_error_at(p, vat, "%s has more entries than its count (%zu)", m2_names[which], st.n);
			mesh_texture(p, mb);
			st.i++;
			continue;
		}
		if (which == M2_UVS) {
			double uv[2];
			uv_value(p, uv);
			list_vector(p, mb, &st, uv, 2, vat);
			continue;
		}
		struct value v = parse_expression(p);
		/* After a face's vector a float is its texture index; after its
		 * third one, a float is the next face (measured in POV-Ray). */
		if (which == M2_FACES && v.kind == VAL_FLOAT && st.face.set && st.face.ntex < 3) {
			size_t nt = mesh_texture_count(mb);
			if (nt == 0)
				parse_error_at(p, vat, "a face's texture index needs a texture_list before face_indices");
			st.face.tex[st.face.ntex++] = list_index(p, v.v[0], nt, "texture", vat);
			continue;
		}
		/* A float stands for the vector of three copies of it, in every
		 * list, as in POV-Ray (vertex_vectors { 3, 0, 1, <0,2,0> }). */
		if (v.kind == VAL_FLOAT) {
			v.v[1] = v.v[2] = v.v[0];
			v.n = 3;
		} else if (v.kind != VAL_VECTOR) {
			parse_error_at(p, vat, "expected a vector in %s, found a %s", m2_names[which], val_kind_name(v.kind));
		}
		list_vector(p, mb, &st, v.v, v.n, vat);
	}
	flush_face(p, mb, &st.face);
	if (st.i < st.n)
		parse_error_at(p, st.at, "%s has %zu %s of the %zu its count says", m2_names[which], st.i,
		               st.i == 1 ? "entry" : "entries", st.n);
	parse_advance(p);
}

/* mesh2_item := vertex_vectors | normal_vectors | uv_vectors | texture_list
 *             | face_indices | normal_indices | uv_indices
 *             | inside_vector VECTOR
 * The lists must come in this order, each at most once. */
static bool parse_mesh2_item(struct parser *p, struct mesh_builder *mb, int *last)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_KEYWORD)
		return false;
	static const enum kw kws[] = {KW_VERTEX_VECTORS, KW_NORMAL_VECTORS, KW_UV_VECTORS, KW_TEXTURE_LIST,
	                              KW_FACE_INDICES, KW_NORMAL_INDICES, KW_UV_INDICES};
	if (t->kw == KW_INSIDE_VECTOR) {
		parse_advance(p);
		mesh_set_inside_vector(mb, parse_vector(p));
		return true;
	}
	for (int i = 0; i < 7; i++) {
		if (t->kw != kws[i])
			continue;
		if (i == *last)
			parse_error(p, "a second %s in this mesh2", m2_names[i]);
		if (i < *last)
			parse_error(p, "%s must come before %s in mesh2", m2_names[i], m2_names[*last]);
		if (i == M2_FACES && mesh_vertex_count(mb) == 0)
			parse_error(p, "face_indices needs vertices before it (vertex_vectors is missing or empty)");
		*last = i;
		parse_advance(p);
		parse_mesh2_list(p, mb, (enum mesh2_list)i);
		return true;
	}
	return false;
}

/* ---- prism ---- */

/* The fewest points each prism spline takes (enum prism_spline order). */
static const int prism_min_points[] = {3, 5, 6, 0};
static const char *const prism_spline_names[] = {"linear_spline", "quadratic_spline", "cubic_spline",
                                                 "bezier_spline"};

struct prism_points {
	double (*pt)[2];
	struct srcpos *pos;
};

static void free_prism_points_cb(void *v)
{
	struct prism_points *pp = v;
	free(pp->pt);
	free(pp->pos);
	free(pp);
}

/* prism '{' { linear_spline | quadratic_spline | cubic_spline | bezier_spline
 *             | linear_sweep | conic_sweep }
 *   FLOAT ',' FLOAT ',' FLOAT ',' POINT { ',' POINT }
 * (the commas are optional; POINT is a 2-D vector <x, z> or a float f,
 * which is <f, f>). The current token is the first after '{'. */
static struct object *parse_prism(struct parser *p, struct srcpos at)
{
	enum prism_spline spline = PRISM_LINEAR_SPLINE;
	bool conic = false;
	for (;;) {
		if (parse_accept_kw(p, KW_LINEAR_SPLINE)) spline = PRISM_LINEAR_SPLINE;
		else if (parse_accept_kw(p, KW_QUADRATIC_SPLINE)) spline = PRISM_QUADRATIC_SPLINE;
		else if (parse_accept_kw(p, KW_CUBIC_SPLINE)) spline = PRISM_CUBIC_SPLINE;
		else if (parse_accept_kw(p, KW_BEZIER_SPLINE)) spline = PRISM_BEZIER_SPLINE;
		else if (parse_accept_kw(p, KW_LINEAR_SWEEP)) conic = false;
		else if (parse_accept_kw(p, KW_CONIC_SWEEP)) conic = true;
		else break;
	}
	double h1 = parse_float(p);
	opt_comma(p);
	double h2 = parse_float(p);
	opt_comma(p);
	struct srcpos nat = parse_peek(p)->pos;
	double count = trunc(parse_float(p)); /* POV-Ray truncates a fraction */
	int min = prism_min_points[spline];
	if (!(count >= min))
		parse_error_at(p, nat, "a %s prism needs at least %d points, found %g", prism_spline_names[spline], min,
		               count);
	if (count > 1e7)
		parse_error_at(p, nat, "a prism has at most 10000000 points, found %g", count);
	int n = (int)count;
	if (spline == PRISM_BEZIER_SPLINE && n % 4 != 0)
		parse_error_at(p, nat, "a bezier_spline prism needs four points per piece, found %d points", n);
	struct prism_points *pp = calloc(1, sizeof *pp);
	if (!pp) abort();
	int slot = parse_own(p, pp, free_prism_points_cb);
	pp->pt = malloc((size_t)n * sizeof *pp->pt);
	pp->pos = malloc((size_t)n * sizeof *pp->pos);
	if (!pp->pt || !pp->pos) abort();
	for (int i = 0; i < n; i++) {
		opt_comma(p);
		struct srcpos vat = parse_peek(p)->pos;
		struct value v = parse_expression(p);
		if (v.kind == VAL_FLOAT)
			v.v[1] = v.v[0];
		else if (v.kind != VAL_VECTOR || v.n != 2)
			parse_error_at(p, vat, "a prism point is a 2-D vector <x, z>, found %s",
			               v.kind == VAL_VECTOR ? (v.n == 3 ? "a 3-D vector" : v.n == 4 ? "a 4-D vector"
			                                                                             : "a 5-D vector")
			                                    : val_kind_name(v.kind));
		pp->pt[i][0] = v.v[0];
		pp->pt[i][1] = v.v[1];
		pp->pos[i] = vat;
	}
	struct prism_report rep;
	struct object *o = prism_new(spline, conic, h1, h2, (const double (*)[2])pp->pt, n, at, &rep);
	if (rep.open_at >= 0) {
		object_free(o);
		parse_error_at(p, pp->pos[rep.open_at],
		               "this %s sub-prism does not close: its start (the point after this one) must come "
		               "again%s",
		               prism_spline_names[spline], spline == PRISM_CUBIC_SPLINE ? ", then an end control point" : "");
	}
	if (rep.closed_last)
		parse_warning_at(p, at, "the last sub-prism of this linear_spline prism is not closed: closing it");
	if (rep.dropped)
		parse_warning_at(p, at, "%d sub-prism%s of this bezier_spline prism %s not closed: ignoring %s", rep.dropped,
		                 rep.dropped == 1 ? "" : "s", rep.dropped == 1 ? "is" : "are", rep.dropped == 1 ? "it" : "them");
	parse_release(p, slot);
	free_prism_points_cb(pp);
	return o;
}

/* ---- objects ---- */

bool parse_is_object_start(enum kw k)
{
	switch (k) {
	case KW_SPHERE: case KW_PLANE: case KW_BOX: case KW_CYLINDER: case KW_CONE: case KW_DISC:
	case KW_TORUS: case KW_TRIANGLE: case KW_SMOOTH_TRIANGLE: case KW_QUADRIC: case KW_CUBIC:
	case KW_QUARTIC: case KW_POLY: case KW_SUPERELLIPSOID: case KW_MESH: case KW_MESH2: case KW_PRISM:
	case KW_TEXT:
	case KW_UNION: case KW_INTERSECTION: case KW_DIFFERENCE: case KW_MERGE: case KW_OBJECT:
	case KW_LIGHT_GROUP:
		return true;
	default:
		return parse_is_object2(k) || parse_is_object3(k);
	}
}

static struct object *parse_object_in(struct parser *p, bool child);

/* clipped_by/bounded_by '{' object { object } '}' | '{' bounded_by/clipped_by '}'
 * Returns the object (an intersection when several), or NULL for the
 * other-modifier form, which *same records. */
static struct object *parse_limit(struct parser *p, enum kw other, bool *same)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	if (parse_accept_kw(p, other)) {
		parse_expect(p, TOK_RBRACE);
		*same = true;
		return NULL;
	}
	struct object *lim = NULL, *group = NULL;
	int slot = -1;
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD || !parse_is_object_start((enum kw)t->kw))
			parse_expected(p, "an object or '}'");
		struct object *o = parse_object_in(p, true);
		if (!lim) {
			lim = o;
			slot = parse_own(p, lim, free_object_cb);
		} else {
			if (!group) {
				group = csg_new(CSG_INTERSECTION, at);
				csg_add(group, lim);
				lim = group;
				p->owned[slot].ptr = group;
			}
			csg_add(group, o);
		}
	}
	if (!lim)
		parse_error_at(p, at, "expected an object in %s", other == KW_BOUNDED_BY ? "clipped_by" : "bounded_by");
	parse_release(p, slot);
	*same = false;
	return lim;
}

/* What an object statement has read, for the modifiers that need more than
 * the object itself. */
struct obj_state {
	struct object *o;
	int slot;                 /* its ownership slot */
	struct shape_args *args;  /* a primitive's arguments, or NULL */
	struct mesh_builder *mb;  /* mesh or mesh2 being read, or NULL */
	bool clip_is_bound, bound_is_clip;
	unsigned flags;           /* flags given to a CSG, for its children */
	size_t lights_from;       /* the scene's lights from here on were read inside it */
	bool light_first;         /* a difference whose body began with a light_source */
	bool uv;                  /* an object-level uv_mapping was given */
};

/* Replace s->o by a primitive rebuilt from s->args (after `open` or
 * `sturm`), moving what the modifiers gave it. */
static void rebuild(struct parser *p, struct obj_state *s)
{
	struct object *old = s->o, *n = build_shape(s->args, old->pos);
	n->xf = old->xf;
	n->has_xf = old->has_xf;
	n->tex = old->tex;
	n->flags = old->flags;
	n->clip = old->clip;
	n->bound = old->bound;
	old->tex = NULL;
	old->clip = old->bound = NULL;
	object_free(old);
	s->o = n;
	p->owned[s->slot].ptr = n;
}

/* object_modifier := texture | pigment | normal | finish | interior
 *   | material | transform_item
 *   | no_shadow | no_image | no_reflection | hollow [BOOL]
 *   | double_illuminate | inverse | clipped_by | bounded_by
 *   | open | sturm | split_union BOOL | uv_mapping */
static bool parse_object_modifier(struct parser *p, struct obj_state *s)
{
	struct object *o = s->o;
	struct xform t;
	if (parse_transform_item(p, &t)) {
		object_transform(o, &t);
		object_transform_textures(o, &t);
		parse_move_lights(p, s->lights_from, &t);
		return true;
	}
	const struct token *tk = parse_peek(p);
	if (tk->kind != TOK_KEYWORD)
		return false;
	if (s->args && parse_object3_modifier(p, o, s->args->kw))
		return true;
	struct srcpos at = tk->pos;
	switch (tk->kw) {
	case KW_TEXTURE:
		parse_texture_layer(p, &o->tex);
		if (s->uv)
			texture_uv_mapping(&o->tex, true);
		return true;
	case KW_PIGMENT:
		parse_pigment(p, &parse_private_texture(p, &o->tex)->pigment);
		if (s->uv)
			texture_uv_mapping(&o->tex, false);
		return true;
	case KW_NORMAL:
		parse_normal(p, &parse_private_texture(p, &o->tex)->normal);
		if (s->uv)
			texture_uv_mapping(&o->tex, false);
		return true;
	case KW_UV_MAPPING:
		/* POV-Ray: the textures, pigments and normals given after it are
		 * uv-mapped; one given before is an error ("uv_mapping must be
		 * specified before texture"). */
		if (o->tex)
			parse_error(p, "uv_mapping must come before the object's texture, pigment and normal");
		parse_advance(p);
		s->uv = true;
		return true;
	case KW_FINISH: parse_finish(p, &parse_private_texture(p, &o->tex)->finish); return true;
	case KW_INTERIOR: parse_interior(p, &o->interior); return true;
	case KW_MATERIAL: {
		/* The material's textures layer on the object's, as texture
		 * statements do; its interior replaces the object's. */
		struct material *m = calloc(1, sizeof *m);
		if (!m) abort();
		int slot = parse_own(p, m, free_material_holder);
		parse_material(p, m);
		if (m->tex) {
			struct texture *top = m->tex;
			m->tex = NULL;
			o->tex = parse_layer_onto(top, o->tex);
		}
		if (m->interior) {
			interior_unref(o->interior);
			o->interior = m->interior;
			m->interior = NULL;
		}
		parse_release(p, slot);
		free(m);
		return true;
	}
	case KW_NO_SHADOW: parse_advance(p); s->flags |= OBJ_NO_SHADOW; return true;
	case KW_NO_IMAGE: parse_advance(p); s->flags |= OBJ_NO_IMAGE; return true;
	case KW_NO_REFLECTION: parse_advance(p); s->flags |= OBJ_NO_REFLECTION; return true;
	case KW_DOUBLE_ILLUMINATE: parse_advance(p); s->flags |= OBJ_DOUBLE_ILLUMINATE; return true;
	case KW_INVERSE: parse_advance(p); o->flags ^= OBJ_INVERSE; return true;
	case KW_HOLLOW:
		parse_advance(p);
		s->flags |= OBJ_HOLLOW;
		if (parse_starts_expression(p) && parse_float(p) == 0)
			s->flags &= ~(unsigned)OBJ_HOLLOW;
		return true;
	case KW_CLIPPED_BY: {
		bool same;
		struct object *c = parse_limit(p, KW_BOUNDED_BY, &same);
		if (same) {
			s->clip_is_bound = true;
		} else {
			if (o->clip && o->clip != o->bound)
				object_free(o->clip);
			o->clip = c;
			s->clip_is_bound = false;
		}
		return true;
	}
	case KW_BOUNDED_BY: {
		bool same;
		struct object *b = parse_limit(p, KW_CLIPPED_BY, &same);
		if (same) {
			s->bound_is_clip = true;
		} else {
			if (o->bound && o->bound != o->clip)
				object_free(o->bound);
			o->bound = b;
			s->bound_is_clip = false;
		}
		return true;
	}
	case KW_OPEN:
	case KW_STURM: {
		bool is_open = tk->kw == KW_OPEN;
		enum kw k = s->args ? s->args->kw : KW_OBJECT;
		bool fits = is_open ? (k == KW_CYLINDER || k == KW_CONE || k == KW_PRISM || k == KW_SOR)
		                    : (k == KW_TORUS || k == KW_CUBIC || k == KW_QUARTIC || k == KW_POLY || k == KW_PRISM ||
		                       k == KW_LATHE || k == KW_SOR);
		if (!fits)
			parse_error_at(p, at, "'%s' applies to %s only", is_open ? "open" : "sturm",
			               is_open ? "cylinder, cone, prism and sor (and inside an isosurface)"
			                       : "torus, cubic, quartic, poly, prism, lathe and sor");
		parse_advance(p);
		bool on = true;
		if (parse_starts_expression(p))
			on = parse_float(p) != 0;
		if (parse_object2_flag(o, k, is_open, on))
			return true;
		if (k == KW_PRISM) {
			/* The prism's points are not kept: set it in place. */
			if (is_open)
				prism_set_open(o, on);
			else
				prism_set_sturm(o, on);
			return true;
		}
		if (is_open)
			s->args->open = on;
		else
			s->args->sturm = on;
		rebuild(p, s);
		return true;
	}
	case KW_SPLIT_UNION: {
		enum csg_kind kind;
		if (!csg_kind_of(o, &kind) || kind != CSG_UNION)
			parse_error_at(p, at, "'split_union' applies to union only");
		parse_advance(p);
		csg_set_split(o, parse_float(p) != 0);
		return true;
	}
	default:
		return false;
	}
}

/* object := primitive '{' args { object_modifier } '}'
 *         | csg '{' { object | object_modifier } '}'
 *         | mesh '{' (IDENT | { mesh_item }) { object_modifier } '}'
 *         | mesh2 '{' (IDENT | { mesh2_item }) { object_modifier } '}'
 *         | object '{' (IDENT | object) { object_modifier } '}'
 * `child`: inside a CSG or a clip, where the default texture is not
 * applied (the parent's texture comes first). The caller owns the result. */
static struct object *parse_object_in(struct parser *p, bool child)
{
	const struct token *t = parse_peek(p);
	enum kw k = (enum kw)t->kw;
	if (k == KW_LIGHT_GROUP)
		return parse_light_group(p, child);
	struct srcpos at = t->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct obj_state s = {0};
	s.lights_from = p->scene->nlights;
	struct shape_args args;
	int mslot = -1;
	switch (k) {
	case KW_OBJECT: {
		const struct token *n = parse_peek(p);
		if (n->kind == TOK_KEYWORD && parse_is_object_start((enum kw)n->kw)) {
			s.o = parse_object_in(p, true);
			break;
		}
		const struct value *v = parse_ident_value(p);
		if (!v)
			parse_expected(p, "an object identifier or an object");
		if (v->kind != VAL_OBJECT)
			parse_wrong_kind(p, v, "an object");
		s.o = object_copy(v->obj);
		s.o->pos = at;
		parse_advance(p);
		parse_place_light_groups(p, s.o);
		break;
	}
	case KW_UNION: s.o = csg_new(CSG_UNION, at); break;
	case KW_MERGE: s.o = csg_new(CSG_MERGE, at); break;
	case KW_INTERSECTION: s.o = csg_new(CSG_INTERSECTION, at); break;
	case KW_DIFFERENCE: s.o = csg_new(CSG_DIFFERENCE, at); break;
	case KW_PRISM:
	case KW_POLYGON:
	case KW_LATHE:
	case KW_SOR:
	case KW_ISOSURFACE:
	case KW_BLOB:
	case KW_HEIGHT_FIELD:
	case KW_SPHERE_SWEEP:
		/* Shapes read by their own parsers; args.kw routes their modifiers. */
		memset(&args, 0, sizeof args);
		args.kw = k;
		s.args = &args;
		if (k == KW_PRISM)
			s.o = parse_prism(p, at);
		else if (k == KW_BLOB || k == KW_HEIGHT_FIELD || k == KW_SPHERE_SWEEP)
			s.o = parse_object3(p, k, at);
		else
			s.o = parse_object2(p, k, at);
		break;
	case KW_TEXT: s.o = parse_text(p, at); break;
	case KW_MESH:
	case KW_MESH2: {
		/* mesh { IDENT ... }: POV-Ray takes a copy of any declared object
		 * there (measured: mesh { M2 } and mesh { Sphere } render as
		 * object { ... }). */
		const struct value *v = parse_ident_value(p);
		if (v) {
			if (v->kind != VAL_OBJECT)
				parse_wrong_kind(p, v, "an object");
			s.o = object_copy(v->obj);
			s.o->pos = at;
			parse_advance(p);
			parse_place_light_groups(p, s.o);
			break;
		}
		s.mb = mesh_builder_new(k == KW_MESH ? MESH_KIND_MESH : MESH_KIND_MESH2);
		mslot = parse_own(p, s.mb, free_mesh_builder_cb);
		break;
	}
	default:
		memset(&args, 0, offsetof(struct shape_args, coef));
		args.kw = k;
		parse_shape_args(p, &args);
		s.args = &args;
		s.o = build_shape(&args, at);
		break;
	}
	bool is_csg = k == KW_UNION || k == KW_MERGE || k == KW_INTERSECTION || k == KW_DIFFERENCE;
	if (s.mb) {
		/* Mesh items come first; the object exists once they are read. */
		int last = -1;
		if (k == KW_MESH)
			while (parse_mesh_item(p, s.mb))
				;
		else
			while (parse_mesh2_item(p, s.mb, &last))
				;
		if (k == KW_MESH2 && last < M2_FACES)
			parse_error_at(p, at, "a mesh2 needs vertex_vectors and face_indices");
		parse_release(p, mslot);
		s.o = mesh_new(s.mb, at);
		s.mb = NULL;
	}
	s.slot = parse_own(p, s.o, free_object_cb);
	while (!parse_accept(p, TOK_RBRACE)) {
		const struct token *tk = parse_peek(p);
		if (is_csg && tk->kind == TOK_KEYWORD && tk->kw == KW_LIGHT_SOURCE) {
			struct object **kids;
			if (k == KW_DIFFERENCE && s.o->ops->children(s.o, &kids) == 0)
				s.light_first = true;
			parse_csg_light(p, s.o);
			continue;
		}
		if (is_csg && tk->kind == TOK_KEYWORD && parse_is_object_start((enum kw)tk->kw)) {
			struct object **kids;
			if (++p->csg_depth > p->lim.csg_depth)
				parse_error(p, "CSG objects nested too deeply (more than %zu levels; lucent --limit csg-depth=N "
				            "raises it)", p->lim.csg_depth);
			struct object *c = parse_object_in(p, true);
			p->csg_depth--;
			/* In POV-Ray a light that comes first in a difference takes
			 * the place of the base, so every object in it is subtracted
			 * (measured: the same image as an intersection of the objects
			 * inverted): the first object is inverted. */
			if (s.light_first && s.o->ops->children(s.o, &kids) == 0)
				c->flags ^= OBJ_INVERSE;
			csg_add(s.o, c);
			continue;
		}
		if (!parse_object_modifier(p, &s)) {
			if (is_csg)
				parse_expected(p, "an object, an object modifier or '}'");
			parse_expected(p, "an object modifier or '}'");
		}
	}
	struct object *o = s.o;
	/* clipped_by { bounded_by } without a bounded_by object (and the
	 * reverse) leaves the object as it is, as in POV-Ray. */
	if (s.clip_is_bound && !s.bound_is_clip && o->bound && !o->clip)
		o->clip = o->bound;
	if (s.bound_is_clip && !s.clip_is_bound && o->clip && !o->bound)
		o->bound = o->clip;
	if (s.flags)
		object_set_flags(o, s.flags);
	/* Unions under an inversion lose their inner surfaces (csg.h). */
	if (csg_kind_of(o, NULL))
		csg_settle(o);
	/* A CSG's texture goes to the children that have none (also when it
	 * is given to object { CsgIdentifier }). */
	if (csg_kind_of(o, NULL) && o->tex)
		object_fill_texture(o, o->tex);
	if (csg_kind_of(o, NULL) && o->interior)
		object_fill_interior(o, o->interior);
	if (!child && p->default_tex)
		object_fill_texture(o, p->default_tex);
	parse_release(p, s.slot);
	return o;
}

struct object *parse_object(struct parser *p, bool scene_level)
{
	return parse_object_in(p, !scene_level);
}

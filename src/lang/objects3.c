/* objects3.c: the arguments and own modifiers of blob, height_field and
 * sphere_sweep,
 * with POV-Ray's rules (measured where the manual is silent: a blob's
 * components and threshold come before the object modifiers; commas are
 * optional; a component's texture, pigment, normal and finish, and its
 * transformations, are the only modifiers it takes; a height field's
 * smooth, water_level and hierarchy go among the object modifiers; a
 * sphere sweep's tolerance comes once, straight after its spheres). The
 * shapes are in src/geom/blob.c, heightfield.c and sweep.c. */
#include "geom/blob.h"
#include "geom/heightfield.h"
#include "geom/sweep.h"
#include "image/formats.h"
#include "image/oiio.h"
#include "lang/parser.h"
#include "scene/fn.h"

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

static void free_cb(void *ptr)
{
	free(ptr);
}

/* The grid size of `function W, H`: at least 2, at most 65536 (a
 * truncated float, as POV-Ray reads it). */
static int grid_size(struct parser *p, const char *what)
{
	struct srcpos at = parse_peek(p)->pos;
	double v = trunc(parse_float(p));
	if (!(v >= 2 && v <= 65536))
		parse_error_at(p, at, "a height_field function's %s must be from 2 to 65536, found %g", what, v);
	return (int)v;
}

/* The 16-bit heights of the samples of an image, as POV-Ray takes them
 * (measured): a palette index i is i * 257; a grey value its 16-bit value
 * (8 bits: v * 257, so 255 is 65535); a colour the red byte above the green
 * one, red * 256 + green (the TGA and PPM convention, which POV-Ray also
 * applies to colour PNG files). */
static void image_heights(const struct oiio_image *im, uint16_t *v)
{
	size_t n = (size_t)im->width * (size_t)im->height;
	int ch = im->channels;
	double maxval = im->bits >= 16 ? 65535 : 255;
	for (size_t i = 0; i < n; i++) {
		if (im->index) {
			v[i] = (uint16_t)(im->index[i] * 257);
			continue;
		}
		double g = im->px[i * (size_t)ch];
		g = g < 0 ? 0 : g > 1 ? 1 : g;
		unsigned s = (unsigned)(g * maxval + 0.5);
		if (ch >= 3) {
			double gr = im->px[i * (size_t)ch + 1];
			gr = gr < 0 ? 0 : gr > 1 ? 1 : gr;
			unsigned r8 = im->bits >= 16 ? s >> 8 : s, g8 = (unsigned)(gr * maxval + 0.5);
			if (im->bits >= 16)
				g8 >>= 8;
			v[i] = (uint16_t)(r8 * 256 + g8);
		} else {
			v[i] = (uint16_t)(im->bits >= 16 ? s : s * 257);
		}
	}
}

static const enum kw hf_types[] = {KW_PNG, KW_GIF, KW_JPEG, KW_TGA, KW_TIFF, KW_EXR, KW_HDR, KW_PPM, KW_PGM,
                                   KW_IFF, KW_SYS, KW_POT};

/* height_field '{' ( [TYPE] STRING [gamma F | srgb] [premultiplied B]
 *                  | function FLOAT ',' FLOAT '{' BODY '}' ) ... */
static struct object *parse_height_field(struct parser *p, struct srcpos at)
{
	int w, h, slot;
	uint16_t *v;
	if (parse_accept_kw(p, KW_FUNCTION)) {
		w = grid_size(p, "width");
		opt_comma(p);
		h = grid_size(p, "height");
		struct srcpos fat = parse_peek(p)->pos;
		struct fn *f = parse_function_body(p);
		if (fn_is_vector(f)) {
			fn_unref(f);
			parse_error_at(p, fat, "a height_field function has one value");
		}
		v = malloc((size_t)w * (size_t)h * sizeof *v);
		if (!v) abort();
		/* Column c is x = c / (w - 1), row r is y = r / (h - 1) (the
		 * image's top row, at z = 1; measured: f = y rises toward -z). */
		for (int r = 0; r < h; r++)
			for (int c = 0; c < w; c++) {
				double args[3] = {(double)c / (w - 1), (double)r / (h - 1), 0};
				v[(size_t)r * (size_t)w + (size_t)c] = heightfield_quantize(fn_eval(f, args));
			}
		fn_unref(f);
		slot = parse_own(p, v, free_cb);
	} else {
		for (size_t k = 0; k < sizeof hf_types / sizeof hf_types[0]; k++)
			if (parse_accept_kw(p, hf_types[k]))
				break;
		if (!parse_starts_expression(p))
			parse_expected(p, "an image file name or 'function' (a height_field's heights)");
		struct srcpos name_at = parse_peek(p)->pos;
		const char *name = parse_string(p);
		/* The heights are data: gamma and premultiplied are read and,
		 * as for POV-Ray's linear data, change nothing here. */
		for (;;) {
			if (parse_accept_kw(p, KW_GAMMA)) {
				if (!parse_accept_kw(p, KW_SRGB))
					parse_float(p);
			} else if (parse_accept_kw(p, KW_PREMULTIPLIED)) {
				parse_float(p);
			} else {
				break;
			}
		}
		char *path = parse_find_file(p, name, name_at.file);
		if (!path)
			parse_error_at(p, name_at, "cannot find height_field image \"%s\" (searched the scene's folder, "
			               "the current folder and the +L paths)", name);
		struct oiio_image im;
		char err[1024];
		int rc = img_is_png(path) ? img_png_read(path, &im, err, sizeof err) : oiio_read(path, &im, err, sizeof err);
		free(path);
		if (rc != 0)
			parse_error_at(p, name_at, "cannot read height_field image \"%s\": %s", name, err);
		w = im.width;
		h = im.height;
		if (w < 2 || h < 2) {
			free(im.px);
			free(im.index);
			parse_error_at(p, name_at, "a height_field image needs at least 2 x 2 pixels, \"%s\" has %d x %d", name,
			               w, h);
		}
		v = malloc((size_t)w * (size_t)h * sizeof *v);
		if (!v) abort();
		image_heights(&im, v);
		free(im.px);
		free(im.index);
		slot = parse_own(p, v, free_cb);
	}
	struct object *o = heightfield_new(w, h, v, at);
	parse_release(p, slot);
	free(v);
	return o;
}

/* sphere_sweep '{' (linear_spline | b_spline | cubic_spline) F { ',' V ',' F } [tolerance F] ...
 * The count is truncated, as POV-Ray reads it; commas are optional. */
static struct object *parse_sphere_sweep(struct parser *p, struct srcpos at)
{
	enum sweep_spline kind;
	if (parse_accept_kw(p, KW_LINEAR_SPLINE))
		kind = SWEEP_LINEAR;
	else if (parse_accept_kw(p, KW_B_SPLINE))
		kind = SWEEP_B_SPLINE;
	else if (parse_accept_kw(p, KW_CUBIC_SPLINE))
		kind = SWEEP_CUBIC;
	else
		parse_expected(p, "linear_spline, b_spline or cubic_spline (a sphere_sweep's interpolation)");
	struct srcpos nat = parse_peek(p)->pos;
	double count = trunc(parse_float(p));
	int least = sweep_min_spheres(kind);
	if (!(count >= least))
		parse_error_at(p, nat, "a %s sphere_sweep needs at least %d spheres, found %g",
		               kind == SWEEP_LINEAR ? "linear_spline" : kind == SWEEP_B_SPLINE ? "b_spline" : "cubic_spline",
		               least, count);
	if (count > 1e7)
		parse_error_at(p, nat, "a sphere_sweep of %g spheres is more than lucent takes (10000000)", count);
	int n = (int)count;
	vec3 *c = malloc((size_t)n * sizeof *c);
	if (!c) abort();
	int cslot = parse_own(p, c, free_cb);
	double *r = malloc((size_t)n * sizeof *r);
	if (!r) abort();
	int rslot = parse_own(p, r, free_cb);
	for (int i = 0; i < n; i++) {
		opt_comma(p);
		c[i] = parse_vector(p);
		opt_comma(p);
		r[i] = parse_float(p);
	}
	struct object *o = sweep_new(kind, c, r, n, at);
	parse_release(p, rslot);
	parse_release(p, cslot);
	free(r);
	free(c);
	if (parse_accept_kw(p, KW_TOLERANCE)) {
		int slot = parse_own(p, o, free_object_cb);
		sweep_set_tolerance(o, parse_float(p));
		parse_release(p, slot);
	}
	return o;
}

bool parse_is_object3(enum kw k)
{
	return k == KW_BLOB || k == KW_HEIGHT_FIELD || k == KW_SPHERE_SWEEP;
}

struct object *parse_object3(struct parser *p, enum kw k, struct srcpos at)
{
	if (k == KW_SPHERE_SWEEP)
		return parse_sphere_sweep(p, at);
	if (k == KW_HEIGHT_FIELD)
		return parse_height_field(p, at);
	return parse_blob(p, at);
}

/* An optional boolean after a flag keyword (on when absent). */
static bool flag_value(struct parser *p)
{
	return parse_starts_expression(p) ? parse_float(p) != 0 : true;
}

bool parse_object3_modifier(struct parser *p, struct object *o, enum kw k)
{
	if (k == KW_HEIGHT_FIELD) {
		if (parse_accept_kw(p, KW_SMOOTH)) {
			heightfield_set_smooth(o, flag_value(p));
			return true;
		}
		if (parse_accept_kw(p, KW_WATER_LEVEL)) {
			heightfield_set_water_level(o, parse_float(p));
			return true;
		}
		if (parse_accept_kw(p, KW_HIERARCHY)) {
			heightfield_set_hierarchy(o, flag_value(p));
			return true;
		}
		return false;
	}
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

/* image_parse.c: the image blocks of image_map, bump_map, image_pattern
 * and material_map: the file (type, name, gamma, premultiplied) and the
 * mapping modifiers, read into a struct image_mapping. What POV-Ray 3.7
 * accepts and rejects here was checked against povray itself. */
#include "lang/parser.h"

#include "image/image.h"
#include "scene/fn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The file type keywords and the extensions POV-Ray tries when the name
 * has none. sys is the platform's own format: the name is taken as it is
 * and the content tells the format. */
static const struct {
	enum kw kw;
	const char *ext[2];
} file_types[] = {
	{KW_PNG, {".png", NULL}},  {KW_GIF, {".gif", NULL}},   {KW_JPEG, {".jpg", ".jpeg"}},
	{KW_TGA, {".tga", NULL}},  {KW_TIFF, {".tif", ".tiff"}}, {KW_EXR, {".exr", NULL}},
	{KW_HDR, {".hdr", NULL}},  {KW_PPM, {".ppm", NULL}},   {KW_PGM, {".pgm", NULL}},
	{KW_IFF, {".iff", NULL}},  {KW_SYS, {NULL, NULL}},
};

static void unref_image(void *img) { image_unref(img); }

static bool has_extension(const char *name)
{
	const char *slash = strrchr(name, '/'), *dot = strrchr(name, '.');
	return dot && (!slash || dot > slash);
}

/* Find the image file: the name as written, or with the type's extension
 * when it has none (with no type keyword, .png, POV-Ray's default output
 * type), in the folders parse_find_file searches. Returns a malloc'd path
 * or NULL. */
static char *find_image(struct parser *p, const char *name, int type, uint32_t from_file)
{
	char buf[4096];
	if (!has_extension(name)) {
		static const char *const png_ext[2] = {".png", NULL};
		const char *const *ext = type >= 0 ? file_types[type].ext : png_ext;
		for (int i = 0; i < 2 && ext[i]; i++) {
			snprintf(buf, sizeof buf, "%s%s", name, ext[i]);
			char *path = parse_find_file(p, buf, from_file);
			if (path)
				return path;
		}
	}
	return parse_find_file(p, name, from_file);
}

/* An integer operand (POV-Ray truncates a float there). */
static int parse_int(struct parser *p, struct srcpos *at)
{
	*at = parse_peek(p)->pos;
	double v = parse_float(p);
	if (v > 1e9 || v < -1e9)
		parse_error_at(p, *at, "%g is out of range here", v);
	return (int)v;
}

/* filter|transmit ( all FLOAT | INDEX , FLOAT ) */
static void parse_palette_amount(struct parser *p, struct image_mapping *m, bool filter, int *slot)
{
	struct srcpos kw_at = p->prev.pos;
	const char *what = filter ? "filter" : "transmit";
	if (parse_accept_kw(p, KW_ALL)) {
		double v = parse_float(p);
		if (filter) {
			m->filter_all = v;
			m->has_filter_all = true;
		} else {
			m->transmit_all = v;
			m->has_transmit_all = true;
		}
		/* `all` sets every palette entry: what was set before it is gone. */
		for (int i = 0; i < m->nentry; i++) {
			if (filter)
				m->entry[i].has_filter = false;
			else
				m->entry[i].has_transmit = false;
		}
		return;
	}
	struct srcpos at;
	int index = parse_int(p, &at);
	parse_accept(p, TOK_COMMA);
	double v = parse_float(p);
	int n = m->img->palette_size;
	if (n == 0)
		parse_error_at(p, kw_at, "'%s %d, ...' needs an image with a palette, and \"%s\" has none (use '%s all')",
		               what, index, m->img->path ? m->img->path : "a function image", what);
	if (index < 0 || index >= n)
		parse_error_at(p, at, "palette index %d is out of range: \"%s\" has %d palette entries (0 to %d)", index,
		               m->img->path, n, n - 1);
	if (*slot >= 0)
		parse_release(p, *slot);
	void *grown = realloc(m->entry, (size_t)(m->nentry + 1) * sizeof *m->entry);
	if (!grown)
		abort();
	m->entry = grown;
	*slot = parse_own(p, m->entry, free);
	memset(&m->entry[m->nentry], 0, sizeof m->entry[0]);
	m->entry[m->nentry].index = index;
	if (filter) {
		m->entry[m->nentry].filter = v;
		m->entry[m->nentry].has_filter = true;
	} else {
		m->entry[m->nentry].transmit = v;
		m->entry[m->nentry].has_transmit = true;
	}
	m->nentry++;
}

/* IMAGE_MAP_MODS: { map_type INT | once | interpolate INT | filter (all
 * FLOAT | INT, FLOAT) | transmit (all FLOAT | INT, FLOAT) | use_alpha
 * | use_index | use_color | use_colour } into *lm (*entry_slot: the parse
 * slot of lm's palette entries, -1 for none). */
static void image_modifiers(struct parser *p, struct image_mapping *lm, int *entry_slot)
{
	for (;;) {
		struct srcpos at;
		if (parse_accept_kw(p, KW_MAP_TYPE)) {
			int v = parse_int(p, &at);
			if (v != 0 && v != 1 && v != 2 && v != 5)
				parse_error_at(p, at, "map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), not %d", v);
			lm->map_type = v;
		} else if (parse_accept_kw(p, KW_INTERPOLATE)) {
			int v = parse_int(p, &at);
			if (v != 2 && v != 3 && v != 4)
				parse_error_at(p, at, "interpolate must be 2 (bilinear), 3 (bicubic) or 4 (normalized distance), not %d", v);
			lm->interpolate = v;
		} else if (parse_accept_kw(p, KW_ONCE)) {
			lm->once = true;
		} else if (parse_accept_kw(p, KW_FILTER)) {
			parse_palette_amount(p, lm, true, entry_slot);
		} else if (parse_accept_kw(p, KW_TRANSMIT)) {
			parse_palette_amount(p, lm, false, entry_slot);
		} else if (parse_accept_kw(p, KW_USE_ALPHA)) {
			lm->use_alpha = true;
		} else if (parse_accept_kw(p, KW_USE_INDEX)) {
			lm->use_index = true;
			lm->use_color = false;
		} else if (parse_accept_kw(p, KW_USE_COLOR) || parse_accept_kw(p, KW_USE_COLOUR)) {
			lm->use_color = true;
			lm->use_index = false;
		} else {
			break;
		}
	}
}

/* function W ',' H '{' FUNCTION_BODY '}': an image of W x H pixels made
 * from a float, pattern or pigment function of x, y (z = 0), as POV-Ray
 * makes it (measured): pixel column i, row j from the top is the function
 * at (i/(W-1), j/(H-1), 0); a pigment gives colour and alpha (1 -
 * transmit; filter is dropped), the others grey; every component is stored
 * in 16 bits as C does it, (unsigned short)(int)(v * 65535) in single
 * precision (0.7000076 gives 45875, not 45874), so values
 * outside [0, 1] wrap (1.5 gives 0.49998, -0.25 gives 0.75003). Returns
 * one reference. The current token is 'function'. */
static struct image *function_image(struct parser *p)
{
	parse_advance(p);
	struct srcpos wat = parse_peek(p)->pos;
	int w = parse_int_of(parse_float(p));
	parse_expect(p, TOK_COMMA);
	struct srcpos hat = parse_peek(p)->pos;
	int h = parse_int_of(parse_float(p));
	if (w < 1)
		parse_error_at(p, wat, "a function image's width must be at least 1, not %d", w);
	if (h < 1)
		parse_error_at(p, hat, "a function image's height must be at least 1, not %d", h);
	struct fn *f = parse_function_body(p);
	bool color = f->pig != NULL;
	float *px = malloc((size_t)w * (size_t)h * 4 * sizeof(float));
	if (!px)
		parse_error_at(p, wat, "out of memory for a %d x %d function image", w, h);
	for (int j = 0; j < h; j++)
		for (int i = 0; i < w; i++) {
			double args[3] = {w > 1 ? (double)i / (w - 1) : 0, h > 1 ? (double)j / (h - 1) : 0, 0};
			double c[5];
			if (color) {
				fn_eval_color(f, args, c);
				c[3] = 1 - c[4];
			} else {
				c[0] = c[1] = c[2] = fn_eval(f, args);
				c[3] = 1;
			}
			float *d = &px[((size_t)j * w + i) * 4];
			for (int k = 0; k < 4; k++) {
				/* in single precision, as POV-Ray; the wrap of (unsigned
				 * short)(int) done without C's undefined overflow */
				double v = trunc((double)((float)c[k] * 65535.0f));
				v = isfinite(v) ? v - 65536.0 * floor(v / 65536.0) : 0;
				d[k] = (float)(v / 65535.0);
			}
		}
	fn_unref(f);
	struct image *img = image_from_pixels(w, h, color ? 4 : 1, px);
	if (!img)
		parse_error_at(p, wat, "out of memory for a %d x %d function image", w, h);
	return img;
}

/* IMAGE_BLOCK_BODY:
 *   [BITMAP_TYPE] STRING [gamma (FLOAT | srgb)] [premultiplied BOOL]
 *   { map_type INT | once | interpolate INT | filter (all FLOAT | INT, FLOAT)
 *   | transmit (all FLOAT | INT, FLOAT) | use_alpha | use_index | use_color
 *   | use_colour }
 *   | function W ',' H '{' FUNCTION_BODY '}' { the same modifiers }
 * BITMAP_TYPE: exr | gif | hdr | iff | jpeg | pgm | png | ppm | sys | tga | tiff */
void parse_image_mapping(struct parser *p, struct image_mapping *m)
{
	*m = (struct image_mapping){.premultiplied = -1};
	/* Read into a copy, handed to m only when complete: if the parse
	 * fails, what was loaded is freed by the parse and m holds nothing. */
	struct image_mapping lm = *m;
	int type = -1;
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_KEYWORD && t->kw == KW_FUNCTION) {
		lm.img = function_image(p);
		int img_slot = parse_own(p, lm.img, unref_image);
		int entry_slot = -1;
		image_modifiers(p, &lm, &entry_slot);
		parse_release(p, img_slot);
		if (entry_slot >= 0)
			parse_release(p, entry_slot);
		*m = lm;
		return;
	}
	if (t->kind == TOK_KEYWORD)
		for (int i = 0; i < (int)(sizeof file_types / sizeof file_types[0]); i++)
			if (t->kw == file_types[i].kw)
				type = i;
	if (type >= 0)
		parse_advance(p);
	if (!parse_starts_expression(p))
		parse_expected(p, type >= 0 ? "an image file name" : "an image file type or file name");
	struct srcpos name_at = parse_peek(p)->pos;
	const char *name = parse_string(p);

	/* gamma and premultiplied belong to the file, in either order. */
	double gamma = 0;
	int premultiplied = -1;
	for (;;) {
		if (parse_accept_kw(p, KW_GAMMA)) {
			if (parse_accept_kw(p, KW_SRGB)) {
				gamma = IMAGE_GAMMA_SRGB;
			} else {
				struct srcpos at = parse_peek(p)->pos;
				gamma = parse_float(p);
				if (!(gamma > 0))
					parse_error_at(p, at, "an image's gamma must be greater than 0, or srgb");
			}
		} else if (parse_accept_kw(p, KW_PREMULTIPLIED)) {
			premultiplied = parse_float(p) != 0;
		} else {
			break;
		}
	}

	char *path = find_image(p, name, type, name_at.file);
	if (!path)
		parse_error_at(p, name_at,
		               "cannot find image file \"%s\" (searched the scene's folder, the current folder and the +L paths)",
		               name);
	char err[1024];
	struct image *img = image_load_opts(path, gamma, premultiplied, err, sizeof err);
	free(path);
	if (!img)
		parse_error_at(p, name_at, "cannot read image file \"%s\": %s", name, err);
	int img_slot = parse_own(p, img, unref_image);
	int entry_slot = -1;
	lm.img = img;
	lm.gamma = gamma;
	lm.premultiplied = premultiplied;

	image_modifiers(p, &lm, &entry_slot);
	/* Handed over: the caller's mapping owns the image and the entries. */
	if (entry_slot >= 0)
		parse_release(p, entry_slot);
	parse_release(p, img_slot);
	*m = lm;
}

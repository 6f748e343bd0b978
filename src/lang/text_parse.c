/* text_parse.c: the text object statement, the search for its font file
 * and the decoding of its string by the global charset. */
#include "lang/parser.h"

#include "font/ttf.h"
#include "geom/shapes.h"
#include "lang/ustr.h"

#include <ctype.h>
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

/* The system's font folder, searched (with its subfolders, to this depth)
 * after the scene's folders: a read-only library path for the file rule. */
static const char SYSTEM_FONTS[] = "/usr/share/fonts/truetype";
enum { SYSTEM_FONTS_DEPTH = 3 };

/* POV-Ray's built-in fonts, by `internal` number. */
static const char *const internal_fonts[] = {"povlogo.ttf", "timrom.ttf", "cyrvetic.ttf", "crystal.ttf"};

/* POV-Ray's own fonts are not ours to ship: when a scene names one that
 * is not installed, a free font of about the same metrics is used. */
static const struct {
	const char *pov;
	const char *subst[2];
} substitutes[] = {
	{"timrom.ttf", {"LiberationSerif-Regular.ttf", "DejaVuSerif.ttf"}},
	{"cyrvetic.ttf", {"LiberationSans-Regular.ttf", "DejaVuSans.ttf"}},
	{"crystal.ttf", {"LiberationMono-Regular.ttf", "DejaVuSansMono.ttf"}},
};

static bool readable_file(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0 && S_ISREG(st.st_mode) && access(path, R_OK) == 0;
}

/* dir/name if it is a readable file: malloc'd, else NULL. */
static char *try_in(const char *dir, const char *name)
{
	char buf[PATH_MAX];
	if ((size_t)snprintf(buf, sizeof buf, "%s/%s", dir, name) >= sizeof buf)
		return NULL;
	if (!readable_file(buf))
		return NULL;
	char *c = strdup(buf);
	if (!c) abort();
	return c;
}

/* name in dir or its subfolders (depth levels down), in name order so the
 * choice does not depend on the file system's order. */
static int cmp_names(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

static char *find_below(const char *dir, const char *name, int depth)
{
	char *hit = try_in(dir, name);
	if (hit || depth == 0)
		return hit;
	DIR *d = opendir(dir);
	if (!d)
		return NULL;
	char **subs = NULL;
	size_t n = 0, cap = 0;
	struct dirent *e;
	while ((e = readdir(d))) {
		if (e->d_name[0] == '.')
			continue;
		char buf[PATH_MAX];
		struct stat st;
		if ((size_t)snprintf(buf, sizeof buf, "%s/%s", dir, e->d_name) >= sizeof buf || stat(buf, &st) != 0 ||
		    !S_ISDIR(st.st_mode))
			continue;
		if (n == cap) {
			cap = cap ? 2 * cap : 16;
			subs = realloc(subs, cap * sizeof *subs);
			if (!subs) abort();
		}
		subs[n] = strdup(buf);
		if (!subs[n]) abort();
		n++;
	}
	closedir(d);
	if (n)
		qsort(subs, n, sizeof *subs, cmp_names);
	for (size_t i = 0; i < n; i++) {
		if (!hit)
			hit = find_below(subs[i], name, depth - 1);
		free(subs[i]);
	}
	free(subs);
	return hit;
}

/* The folder of file `file` of the parse (malloc'd), or NULL. */
static char *folder_of(struct parser *p, uint32_t file)
{
	const struct srcfile *sf = src_file(p->sm, file);
	const char *slash = sf ? strrchr(sf->path, '/') : NULL;
	if (!slash)
		return NULL;
	char *c = malloc((size_t)(slash - sf->path) + 2);
	if (!c) abort();
	if (slash == sf->path)
		strcpy(c, "/");
	else
		sprintf(c, "%.*s", (int)(slash - sf->path), sf->path);
	return c;
}

/* Search the scene's places for name: the folder of the file holding the
 * statement, the scene's folder, the current folder, the +L paths, the
 * stdlib. *system is set when it was found in the system's fonts instead
 * (searched last). malloc'd path, or NULL. */
static char *search(struct parser *p, const char *name, uint32_t from, bool *system)
{
	*system = false;
	if (name[0] == '/') {
		if (!readable_file(name))
			return NULL;
		char *c = strdup(name);
		if (!c) abort();
		return c;
	}
	char *hit = NULL;
	uint32_t files[2] = {from, p->frames[0].file};
	for (int i = 0; i < 2 && !hit; i++) {
		char *dir = folder_of(p, files[i]);
		if (dir)
			hit = try_in(dir, name);
		free(dir);
	}
	if (!hit && readable_file(name)) {
		hit = strdup(name);
		if (!hit) abort();
	}
	for (size_t i = 0; !hit && i < p->o->nlib_paths; i++)
		hit = try_in(p->o->lib_paths[i], name);
	if (!hit && p->o->stdlib_dir)
		hit = try_in(p->o->stdlib_dir, name);
	if (!hit && !strchr(name, '/')) {
		hit = find_below(SYSTEM_FONTS, name, SYSTEM_FONTS_DEPTH);
		*system = hit != NULL;
	}
	return hit;
}

/* Is the resolved path inside the system's font folder? */
static bool in_system_fonts(const char *path)
{
	char *r = realpath(path, NULL), *root = realpath(SYSTEM_FONTS, NULL);
	size_t n = root ? strlen(root) : 0;
	bool in = r && root && strncmp(r, root, n) == 0 && r[n] == '/';
	free(r);
	free(root);
	return in;
}

/* The fonts this parse has loaded, by the name a statement gave and the
 * file that statement is in (the search starts in that file's folder):
 * shapes.inc's Circle_Text makes a text object per letter, and each
 * searched the folders and read the font anew (300 letters: 3,300 files
 * opened, 43,000 stat calls). */
struct font_cache {
	struct font_entry {
		char *name;
		uint32_t file;
		struct ttf_font *font;
	} *v;
	size_t n, cap;
};

void parse_fonts_free(struct parser *p)
{
	struct font_cache *c = p->fonts;
	if (!c)
		return;
	for (size_t i = 0; i < c->n; i++) {
		free(c->v[i].name);
		ttf_free(c->v[i].font);
	}
	free(c->v);
	free(c);
	p->fonts = NULL;
}

static struct ttf_font *cached_font(const struct parser *p, const char *name, uint32_t file)
{
	const struct font_cache *c = p->fonts;
	for (size_t i = 0; c && i < c->n; i++)
		if (c->v[i].file == file && strcmp(c->v[i].name, name) == 0)
			return c->v[i].font;
	return NULL;
}

static void cache_font(struct parser *p, const char *name, uint32_t file, struct ttf_font *f)
{
	if (!p->fonts) {
		p->fonts = calloc(1, sizeof *p->fonts);
		if (!p->fonts) abort();
	}
	struct font_cache *c = p->fonts;
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 4;
		c->v = realloc(c->v, c->cap * sizeof *c->v);
		if (!c->v) abort();
	}
	char *copy = strdup(name);
	if (!copy) abort();
	c->v[c->n++] = (struct font_entry){copy, file, f};
}

/* The font the scene names, found and loaded once per parse (the parse
 * owns it: parse_fonts_free); a substitute with a warning for POV-Ray's
 * own fonts when they are not installed; an error at `at` when there is
 * none. */
static struct ttf_font *open_font(struct parser *p, const char *name, struct srcpos at)
{
	struct ttf_font *known = cached_font(p, name, at.file);
	if (known)
		return known;
	bool system;
	char *path = search(p, name, at.file, &system);
	if (!path && !strchr(name, '.')) {
		/* POV-Ray tries the name with .ttf appended. */
		char buf[PATH_MAX];
		snprintf(buf, sizeof buf, "%s.ttf", name);
		path = search(p, buf, at.file, &system);
	}
	if (!path) {
		const char *base = strrchr(name, '/') ? strrchr(name, '/') + 1 : name;
		for (size_t i = 0; !path && i < sizeof substitutes / sizeof *substitutes; i++) {
			if (strcasecmp(base, substitutes[i].pov) != 0)
				continue;
			for (int k = 0; !path && k < 2; k++) {
				path = find_below(SYSTEM_FONTS, substitutes[i].subst[k], SYSTEM_FONTS_DEPTH);
				if (path) {
					system = true;
					parse_warning_at(p, at, "font \"%s\" not found (it comes with POV-Ray): using %s, "
					                 "a free font of similar metrics", name, path);
				}
			}
		}
	}
	if (!path)
		parse_error_at(p, at, "cannot find font file \"%s\" (searched the scene's folder, the current folder, "
		               "+L paths, the stdlib and %s)", name, SYSTEM_FONTS);
	int slot = parse_own(p, path, free);
	if (!system && !in_system_fonts(path))
		parse_check_access(p, path, name, false, "text", at);
	char err[256];
	struct ttf_font *f = ttf_load(path, err, sizeof err);
	if (!f)
		parse_error_at(p, at, "cannot use font file \"%s\": %s", name, err);
	parse_release(p, slot);
	free(path);
	cache_font(p, name, at.file, f);
	return f;
}

/* The length of the UTF-8 sequence at s (n bytes left) and its code point
 * in *c; 0 if it is not a valid sequence. */
static int utf8_seq(const unsigned char *s, size_t n, uint32_t *c)
{
	int len;
	uint32_t v, min;
	if (s[0] < 0x80)
		return *c = s[0], 1;
	if ((s[0] & 0xE0) == 0xC0) len = 2, v = s[0] & 0x1F, min = 0x80;
	else if ((s[0] & 0xF0) == 0xE0) len = 3, v = s[0] & 0x0F, min = 0x800;
	else if ((s[0] & 0xF8) == 0xF0) len = 4, v = s[0] & 0x07, min = 0x10000;
	else return 0;
	if ((size_t)len > n)
		return 0;
	for (int i = 1; i < len; i++) {
		if ((s[i] & 0xC0) != 0x80)
			return 0;
		v = v << 6 | (s[i] & 0x3F);
	}
	if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF))
		return 0;
	*c = v;
	return len;
}

/* Under charset ascii POV-Ray looks a character code of 0x80 or more up in
 * the font's own Macintosh table (cmap platform 1; ttf.c reads it, codes
 * past 0xFF included, as POV-Ray does): measured with cyrvetic.ttf, whose
 * Mac table is not Mac Roman, and timrom.ttf (tests/lang/text-mac-cmap).
 * A font without one is read as if its Mac table were Mac Roman: "\u00e9"
 * is the glyph of U+00C8 (Mac Roman 0xE9), "\u00d6" that of U+00F7, and a
 * code above 0xFF has no glyph. The Unicode characters of Mac Roman's
 * codes 0x80..0xFF: */
static const uint16_t mac_roman[128] = {
	0x00C4, 0x00C5, 0x00C7, 0x00C9, 0x00D1, 0x00D6, 0x00DC, 0x00E1, 0x00E0, 0x00E2, 0x00E4, 0x00E3, 0x00E5,
	0x00E7, 0x00E9, 0x00E8, 0x00EA, 0x00EB, 0x00ED, 0x00EC, 0x00EE, 0x00EF, 0x00F1, 0x00F3, 0x00F2, 0x00F4,
	0x00F6, 0x00F5, 0x00FA, 0x00F9, 0x00FB, 0x00FC, 0x2020, 0x00B0, 0x00A2, 0x00A3, 0x00A7, 0x2022, 0x00B6,
	0x00DF, 0x00AE, 0x00A9, 0x2122, 0x00B4, 0x00A8, 0x2260, 0x00C6, 0x00D8, 0x221E, 0x00B1, 0x2264, 0x2265,
	0x00A5, 0x00B5, 0x2202, 0x2211, 0x220F, 0x03C0, 0x222B, 0x00AA, 0x00BA, 0x03A9, 0x00E6, 0x00F8, 0x00BF,
	0x00A1, 0x00AC, 0x221A, 0x0192, 0x2248, 0x2206, 0x00AB, 0x00BB, 0x2026, 0x00A0, 0x00C0, 0x00C3, 0x00D5,
	0x0152, 0x0153, 0x2013, 0x2014, 0x201C, 0x201D, 0x2018, 0x2019, 0x00F7, 0x25CA, 0x00FF, 0x0178, 0x2044,
	0x20AC, 0x2039, 0x203A, 0xFB01, 0xFB02, 0x2021, 0x00B7, 0x201A, 0x201E, 0x2030, 0x00C2, 0x00CA, 0x00C1,
	0x00CB, 0x00C8, 0x00CD, 0x00CE, 0x00CF, 0x00CC, 0x00D3, 0x00D4, 0xF8FF, 0x00D2, 0x00DA, 0x00DB, 0x00D9,
	0x0131, 0x02C6, 0x02DC, 0x00AF, 0x02D8, 0x02D9, 0x02DA, 0x00B8, 0x02DD, 0x02DB, 0x02C7,
};

/* The code points of string s by the scene's charset, into a malloc'd
 * array (*n of them). A string holds the file's bytes and characters given
 * by their codes (ustr.h: \uNNNN, chr): under charset utf8 (and sys) a
 * code is that character, under ascii it is looked up as POV-Ray does
 * (mac_roman above). A byte that begins no UTF-8 sequence is that code.
 * With charset ascii (POV-Ray's default) a UTF-8 sequence from the file
 * becomes one space per byte, with a warning, as POV-Ray does. */
static uint32_t *decode(struct parser *p, const struct ttf_font *font, const char *s, size_t *n, struct srcpos at)
{
	size_t len = strlen(s);
	uint32_t *out = malloc((len ? len : 1) * sizeof *out);
	if (!out) abort();
	const unsigned char *u = (const unsigned char *)s;
	bool ascii = p->scene->gs.charset == 0;
	bool warned = false;
	size_t k = 0;
	for (size_t i = 0; i < len;) {
		uint32_t c;
		size_t cl;
		if (ustr_is_coded(s + i)) {
			c = ustr_get(s + i, &cl);
			if (ascii && c >= 0x80) {
				if (ttf_has_mac_cmap(font))
					c |= TTF_MAC;
				else
					c = c <= 0xFF ? mac_roman[c - 0x80] : 0xFFFF; /* U+FFFF: no glyph in any font */
			}
			out[k++] = c;
			i += cl;
			continue;
		}
		int l = utf8_seq(u + i, len - i, &c);
		if (l == 0) {
			out[k++] = u[i++];
			continue;
		}
		if (ascii && l > 1) {
			if (!warned)
				parse_warning_at(p, at, "non-ASCII character in text with charset ascii: replaced by spaces "
				                 "(global_settings { charset utf8 } reads it)");
			warned = true;
			for (int j = 0; j < l; j++)
				out[k++] = ' ';
			i += (size_t)l;
			continue;
		}
		out[k++] = c;
		i += (size_t)l;
	}
	*n = k;
	return out;
}

/* A string literal under charset utf8 (or sys), from its first non-ASCII
 * byte at i: each well-formed UTF-8 sequence becomes one character, as
 * POV-Ray decodes it when the string is read (measured: strlen of "aéb€c"
 * is 5, asc gives 233 and 8364; a 4-byte sequence, beyond POV-Ray's
 * 16-bit characters, is one U+FFFD). A byte that begins no well-formed
 * sequence stays as it is (POV-Ray reads garbage there). */
static const char *utf8_literal(struct parser *p, const char *s, size_t len, size_t i)
{
	/* A 2-byte sequence grows to 4 bytes: at most twice the length. */
	char *t = malloc(2 * len + 1);
	if (!t) abort();
	memcpy(t, s, i);
	size_t o = i;
	while (i < len) {
		const unsigned char *u = (const unsigned char *)s + i;
		size_t l;
		ustr_get(s + i, &l);
		uint32_t code = 0;
		size_t n = 0;
		if (l == 1 && u[0] >= 0xC2 && u[0] <= 0xDF && i + 1 < len && (u[1] & 0xC0) == 0x80) {
			code = (uint32_t)(u[0] & 0x1F) << 6 | (u[1] & 0x3F);
			n = 2;
		} else if (l == 1 && u[0] >= 0xE0 && u[0] <= 0xEF && i + 2 < len && (u[1] & 0xC0) == 0x80 &&
		           (u[2] & 0xC0) == 0x80) {
			code = (uint32_t)(u[0] & 0x0F) << 12 | (uint32_t)(u[1] & 0x3F) << 6 | (u[2] & 0x3F);
			n = code >= 0x800 ? 3 : 0;
		} else if (l == 1 && u[0] >= 0xF0 && u[0] <= 0xF4 && i + 3 < len && (u[1] & 0xC0) == 0x80 &&
		           (u[2] & 0xC0) == 0x80 && (u[3] & 0xC0) == 0x80) {
			code = 0xFFFD;
			n = 4;
		}
		if (n) {
			o += ustr_put(t + o, code);
			i += n;
		} else {
			memcpy(t + o, s + i, l);
			o += l;
			i += l;
		}
	}
	const char *r = parse_intern(p, t, o);
	free(t);
	return r;
}

const char *parse_charset_literal(struct parser *p, const char *s, struct srcpos at)
{
	size_t len = strlen(s);
	size_t i = 0, l;
	for (; i < len; i += l) {
		ustr_get(s + i, &l);
		if (l == 1 && (unsigned char)s[i] >= 0x80)
			break;
	}
	if (i == len)
		return s;
	if (p->scene->gs.charset != 0)
		return utf8_literal(p, s, len, i);
	char *t = malloc(len + 1);
	if (!t) abort();
	memcpy(t, s, len + 1);
	for (; i < len; i += l) {
		ustr_get(t + i, &l);
		if (l == 1 && (unsigned char)t[i] >= 0x80)
			t[i] = ' ';
	}
	parse_warning_at(p, at, "non-ASCII character in a string under charset ascii: replaced by a space, as POV-Ray does "
	                 "(global_settings { charset utf8 } before the string reads it)");
	const char *r = parse_intern(p, t, len);
	free(t);
	return r;
}

/* text '{' ( ttf STRING | internal FLOAT ) STRING FLOAT [','] VECTOR
 *   { object_modifier } '}'
 * The current token is the first after '{'; reads up to the modifiers. */
struct object *parse_text(struct parser *p, struct srcpos at)
{
	struct srcpos fat = parse_peek(p)->pos;
	const char *name;
	if (parse_accept_kw(p, KW_TTF)) {
		fat = parse_peek(p)->pos;
		name = parse_string(p);
	} else if (parse_accept_kw(p, KW_INTERNAL)) {
		double k = parse_float(p);
		/* POV-Ray: an out of range number is font 0. */
		int i = k >= 0 && k < 4 ? (int)k : 0;
		name = internal_fonts[i];
	} else {
		parse_expected(p, "ttf or internal");
	}
	struct ttf_font *font = open_font(p, name, fat);
	struct srcpos sat = parse_peek(p)->pos;
	const char *str = parse_string(p);
	parse_accept(p, TOK_COMMA);
	double thick = parse_float(p);
	parse_accept(p, TOK_COMMA);
	vec3 off = parse_vector(p);
	size_t n;
	uint32_t *codes = decode(p, font, str, &n, sat);
	int cslot = parse_own(p, codes, free);
	uint32_t bad;
	struct object *o = text_new(font, codes, n, thick, off.x, off.y, at, &bad);
	if (bad) {
		object_free(o);
		parse_error_at(p, fat, "font file \"%s\" is damaged: the glyph of character U+%04X cannot be read", name,
		               bad == 0xFFFFFFFFu ? 0 : bad);
	}
	parse_release(p, cslot);
	free(codes);
	return o;
}

/* ttf.c: the TrueType reader (see ttf.h). The file is kept whole in
 * memory; tables are found once at load, glyphs are decoded on demand.
 * All numbers in a TrueType file are big-endian. */
#include "font/ttf.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How deep composite glyphs may nest (the spec sets no limit; a damaged
 * font could loop forever). */
enum { MAX_COMPOSITE_DEPTH = 8 };

/* Glyph flags (simple glyphs). */
enum {
	PT_ON_CURVE = 0x01,
	PT_X_SHORT = 0x02,
	PT_Y_SHORT = 0x04,
	PT_REPEAT = 0x08,
	PT_X_SAME = 0x10, /* with X_SHORT: the short x is positive */
	PT_Y_SAME = 0x20,
};

/* Component flags (composite glyphs). */
enum {
	CMP_ARGS_ARE_WORDS = 0x0001,
	CMP_ARGS_ARE_XY = 0x0002,
	CMP_HAVE_SCALE = 0x0008,
	CMP_MORE = 0x0020,
	CMP_HAVE_XY_SCALE = 0x0040,
	CMP_HAVE_2X2 = 0x0080,
};

enum cmap_kind { CMAP_NONE, CMAP_FMT0, CMAP_FMT4, CMAP_FMT6, CMAP_FMT12 };

struct kern_pair {
	uint32_t key; /* left << 16 | right */
	int value;
};

struct ttf_font {
	unsigned char *data;
	size_t size;
	size_t glyf, glyf_len, loca, hmtx, hmtx_len, cmap;
	struct kern_pair *pairs; /* sorted by key (the spec asks fonts to sort
	                          * them; POV-Ray's timrom.ttf does not) */
	unsigned npairs;
	unsigned upem, nglyphs, nhmetrics;
	bool long_loca;
	enum cmap_kind cmap_kind;
	bool symbol; /* the cmap is a (3, 0) symbol map */
	size_t mac;  /* the Macintosh (1, 0) subtable, format 0 or 6 ... */
	enum cmap_kind mac_kind; /* ... CMAP_NONE when there is none */
	struct ttf_shared_outline **shared; /* nglyphs outlines read so far (NULL: not yet) */
};

/* ---- reading ---- */

static bool in_range(const struct ttf_font *f, size_t off, size_t len)
{
	return off <= f->size && len <= f->size - off;
}

/* Unchecked big-endian reads: callers check the range first. */
static unsigned u8(const struct ttf_font *f, size_t o) { return f->data[o]; }
static unsigned u16(const struct ttf_font *f, size_t o) { return (unsigned)f->data[o] << 8 | f->data[o + 1]; }
static int s16(const struct ttf_font *f, size_t o) { return (int16_t)u16(f, o); }
static uint32_t u32(const struct ttf_font *f, size_t o)
{
	return (uint32_t)u16(f, o) << 16 | u16(f, o + 2);
}

static void set_err(char *err, size_t errlen, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
	if (!err || !errlen)
		return;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(err, errlen, fmt, ap);
	va_end(ap);
}

/* The offset and length of table `tag` in the font whose table directory
 * is at dir; false if it is missing or runs past the file. */
static bool find_table(const struct ttf_font *f, size_t dir, const char *tag, size_t *off, size_t *len)
{
	unsigned n = u16(f, dir + 4);
	if (!in_range(f, dir + 12, (size_t)n * 16))
		return false;
	for (unsigned i = 0; i < n; i++) {
		size_t e = dir + 12 + (size_t)i * 16;
		if (memcmp(f->data + e, tag, 4) != 0)
			continue;
		*off = u32(f, e + 8);
		*len = u32(f, e + 12);
		return in_range(f, *off, *len);
	}
	return false;
}

/* Choose the character map: a Unicode one (3,10 format 12; 3,1 or 0,*
 * format 4 or 12), else a symbol map (3,0), else the Macintosh roman one
 * (1,0 format 0 or 6). */
static void pick_cmap(struct ttf_font *f, size_t cmap, size_t len)
{
	if (len < 4)
		return;
	unsigned n = u16(f, cmap + 2);
	if (!in_range(f, cmap + 4, (size_t)n * 8))
		return;
	int best = -1;
	for (unsigned i = 0; i < n; i++) {
		size_t e = cmap + 4 + (size_t)i * 8;
		unsigned pid = u16(f, e), eid = u16(f, e + 2);
		size_t sub = cmap + u32(f, e + 4);
		if (!in_range(f, sub, 2))
			continue;
		unsigned fmt = u16(f, sub);
		enum cmap_kind k = fmt == 0 ? CMAP_FMT0 : fmt == 4 ? CMAP_FMT4 : fmt == 6 ? CMAP_FMT6
		                 : fmt == 12 ? CMAP_FMT12 : CMAP_NONE;
		if (k == CMAP_NONE)
			continue;
		if (pid == 1 && eid == 0 && (k == CMAP_FMT0 || k == CMAP_FMT6) && f->mac_kind == CMAP_NONE) {
			f->mac = sub;
			f->mac_kind = k;
		}
		int rank = 0;
		if (pid == 3 && eid == 10) rank = 5;
		else if (pid == 3 && eid == 1) rank = 4;
		else if (pid == 0) rank = 3;
		else if (pid == 3 && eid == 0) rank = 2;
		else if (pid == 1 && eid == 0) rank = 1;
		if (rank > best) {
			best = rank;
			f->cmap = sub;
			f->cmap_kind = k;
			f->symbol = rank == 2;
		}
	}
}

static int cmp_pairs(const void *a, const void *b)
{
	uint32_t x = ((const struct kern_pair *)a)->key, y = ((const struct kern_pair *)b)->key;
	return x < y ? -1 : x > y;
}

/* The first horizontal format-0 kern subtable's pairs. */
static void find_kern(struct ttf_font *f, size_t kern, size_t len)
{
	if (len < 4 || u16(f, kern) != 0)
		return;
	unsigned n = u16(f, kern + 2);
	size_t at = kern + 4;
	for (unsigned i = 0; i < n; i++) {
		if (!in_range(f, at, 14))
			return;
		unsigned sublen = u16(f, at + 2), coverage = u16(f, at + 4);
		/* format (high byte) 0, horizontal (bit 0), not minimum values
		 * (bit 1) and not cross-stream (bit 2). */
		if ((coverage >> 8) == 0 && (coverage & 7) == 1) {
			unsigned np = u16(f, at + 6);
			if (in_range(f, at + 14, (size_t)np * 6) && np) {
				f->pairs = malloc(np * sizeof *f->pairs);
				if (!f->pairs) abort();
				for (unsigned k = 0; k < np; k++) {
					f->pairs[k].key = u32(f, at + 14 + 6 * (size_t)k);
					f->pairs[k].value = s16(f, at + 18 + 6 * (size_t)k);
				}
				qsort(f->pairs, np, sizeof *f->pairs, cmp_pairs);
				f->npairs = np;
			}
			return;
		}
		if (sublen < 6)
			return;
		at += sublen;
	}
}

struct ttf_font *ttf_load_mem(const unsigned char *data, size_t size, char *err, size_t errlen)
{
	struct ttf_font *f = calloc(1, sizeof *f);
	if (!f) abort();
	f->data = malloc(size ? size : 1);
	if (!f->data) abort();
	memcpy(f->data, data, size);
	f->size = size;
	size_t dir = 0;
	if (size >= 12 && memcmp(data, "ttcf", 4) == 0) {
		/* A collection: the first font. */
		if (u32(f, 8) == 0 || !in_range(f, 12, 4))
			goto bad;
		dir = u32(f, 12);
	}
	if (!in_range(f, dir, 12))
		goto bad;
	uint32_t tag = u32(f, dir);
	if (tag == 0x4F54544Fu) { /* 'OTTO' */
		set_err(err, errlen, "it is an OpenType font with CFF outlines, not TrueType outlines");
		ttf_free(f);
		return NULL;
	}
	if (tag != 0x00010000u && tag != 0x74727565u) /* 'true' */
		goto bad;
	size_t off, len;
	if (!find_table(f, dir, "head", &off, &len) || len < 54)
		goto missing_head;
	f->upem = u16(f, off + 18);
	f->long_loca = s16(f, off + 50) != 0;
	if (f->upem == 0)
		goto missing_head;
	if (!find_table(f, dir, "maxp", &off, &len) || len < 6) {
		set_err(err, errlen, "its maxp table is missing or damaged");
		goto fail;
	}
	f->nglyphs = u16(f, off + 4);
	if (!find_table(f, dir, "hhea", &off, &len) || len < 36) {
		set_err(err, errlen, "its hhea table is missing or damaged");
		goto fail;
	}
	f->nhmetrics = u16(f, off + 34);
	if (!find_table(f, dir, "hmtx", &f->hmtx, &f->hmtx_len) || f->nhmetrics == 0 ||
	    f->hmtx_len < (size_t)f->nhmetrics * 4) {
		set_err(err, errlen, "its hmtx table is missing or damaged");
		goto fail;
	}
	if (!find_table(f, dir, "glyf", &f->glyf, &f->glyf_len)) {
		set_err(err, errlen, "it has no glyf table (glyph outlines)");
		goto fail;
	}
	if (!find_table(f, dir, "loca", &f->loca, &len) || len < ((size_t)f->nglyphs + 1) * (f->long_loca ? 4 : 2)) {
		set_err(err, errlen, "its loca table is missing or damaged");
		goto fail;
	}
	if (!find_table(f, dir, "cmap", &off, &len)) {
		set_err(err, errlen, "it has no cmap table (character map)");
		goto fail;
	}
	pick_cmap(f, off, len);
	if (f->cmap_kind == CMAP_NONE) {
		set_err(err, errlen, "it has no character map lucent can read (formats 0, 4, 6 and 12)");
		goto fail;
	}
	if (find_table(f, dir, "kern", &off, &len))
		find_kern(f, off, len);
	return f;
missing_head:
	set_err(err, errlen, "its head table is missing or damaged");
	goto fail;
bad:
	set_err(err, errlen, "it is not a TrueType font");
fail:
	ttf_free(f);
	return NULL;
}

struct ttf_font *ttf_load(const char *path, char *err, size_t errlen)
{
	FILE *fp = fopen(path, "rb");
	if (!fp) {
		set_err(err, errlen, "cannot open it");
		return NULL;
	}
	size_t cap = 1 << 16, n = 0;
	unsigned char *buf = malloc(cap);
	if (!buf) abort();
	for (;;) {
		n += fread(buf + n, 1, cap - n, fp);
		if (n < cap)
			break;
		if (cap >= (size_t)1 << 30) { /* no font is this large */
			fclose(fp);
			free(buf);
			set_err(err, errlen, "it is larger than 1 GiB");
			return NULL;
		}
		cap *= 2;
		buf = realloc(buf, cap);
		if (!buf) abort();
	}
	bool failed = ferror(fp);
	fclose(fp);
	if (failed) {
		free(buf);
		set_err(err, errlen, "cannot read it");
		return NULL;
	}
	struct ttf_font *f = ttf_load_mem(buf, n, err, errlen);
	free(buf);
	return f;
}

void ttf_free(struct ttf_font *f)
{
	if (!f)
		return;
	if (f->shared)
		for (unsigned g = 0; g < f->nglyphs; g++)
			ttf_outline_release(f->shared[g]);
	free(f->shared);
	free(f->data);
	free(f->pairs);
	free(f);
}

unsigned ttf_units_per_em(const struct ttf_font *f)
{
	return f->upem;
}

/* ---- character map ---- */

/* The glyph of code c in the subtable at s, of the given kind. A code
 * past the 256 of a format-0 table reads the bytes that follow it in the
 * file when it is the Mac table read for charset ascii, as POV-Ray 3.7
 * does (measured: cyrvetic.ttf's "\u0116" under charset ascii is its
 * "A", the byte 0x116 places into its Mac table). */
static unsigned lookup_in(const struct ttf_font *f, size_t s, enum cmap_kind kind, uint32_t c, bool spill)
{
	switch (kind) {
	case CMAP_FMT0:
		if (c >= 256 && !spill)
			return 0;
		return in_range(f, s + 6, (size_t)c + 1) ? u8(f, s + 6 + c) : 0;
	case CMAP_FMT6: {
		if (!in_range(f, s, 10))
			return 0;
		unsigned first = u16(f, s + 6), count = u16(f, s + 8);
		if (c < first || c - first >= count || !in_range(f, s + 10 + 2 * (size_t)(c - first), 2))
			return 0;
		return u16(f, s + 10 + 2 * (size_t)(c - first));
	}
	case CMAP_FMT4: {
		if (c > 0xFFFF || !in_range(f, s, 14))
			return 0;
		unsigned nseg = u16(f, s + 6) / 2;
		size_t ends = s + 14, starts = ends + 2 * (size_t)nseg + 2, deltas = starts + 2 * (size_t)nseg,
		       ranges = deltas + 2 * (size_t)nseg;
		if (!in_range(f, ends, 8 * (size_t)nseg + 2))
			return 0;
		/* The segments are sorted by their end: binary search. */
		unsigned lo = 0, hi = nseg;
		while (lo < hi) {
			unsigned mid = (lo + hi) / 2;
			if (u16(f, ends + 2 * (size_t)mid) < c)
				lo = mid + 1;
			else
				hi = mid;
		}
		if (lo == nseg)
			return 0;
		size_t i = lo;
		unsigned start = u16(f, starts + 2 * i);
		if (c < start)
			return 0;
		unsigned delta = u16(f, deltas + 2 * i), ro = u16(f, ranges + 2 * i);
		if (ro == 0)
			return (c + delta) & 0xFFFF;
		size_t at = ranges + 2 * i + ro + 2 * (size_t)(c - start);
		if (!in_range(f, at, 2))
			return 0;
		unsigned g = u16(f, at);
		return g ? (g + delta) & 0xFFFF : 0;
	}
	case CMAP_FMT12: {
		if (!in_range(f, s, 16))
			return 0;
		uint32_t n = u32(f, s + 12);
		if (!in_range(f, s + 16, (size_t)n * 12))
			return 0;
		uint32_t lo = 0, hi = n;
		while (lo < hi) {
			uint32_t mid = lo + (hi - lo) / 2;
			size_t g = s + 16 + (size_t)mid * 12;
			if (u32(f, g + 4) < c)
				lo = mid + 1;
			else
				hi = mid;
		}
		if (lo == n)
			return 0;
		size_t g = s + 16 + (size_t)lo * 12;
		uint32_t start = u32(f, g);
		return c < start ? 0 : u32(f, g + 8) + (c - start);
	}
	case CMAP_NONE:
		break;
	}
	return 0;
}

static unsigned lookup(const struct ttf_font *f, uint32_t c)
{
	return lookup_in(f, f->cmap, f->cmap_kind, c, false);
}

bool ttf_has_mac_cmap(const struct ttf_font *f)
{
	return f->mac_kind != CMAP_NONE;
}

unsigned ttf_glyph_index(const struct ttf_font *f, uint32_t c)
{
	if (c & TTF_MAC) {
		unsigned g = f->mac_kind != CMAP_NONE ? lookup_in(f, f->mac, f->mac_kind, c & ~TTF_MAC, true) : 0;
		return g < f->nglyphs ? g : 0;
	}
	unsigned g = lookup(f, c);
	if (!g && f->symbol && c < 0x100)
		g = lookup(f, 0xF000 + c);
	return g < f->nglyphs ? g : 0;
}

/* ---- metrics and kerning ---- */

/* The byte range of glyph g in glyf; false if out of range or damaged. */
static bool glyph_range(const struct ttf_font *f, unsigned g, size_t *off, size_t *len)
{
	if (g >= f->nglyphs)
		return false;
	size_t a, b;
	if (f->long_loca) {
		a = u32(f, f->loca + 4 * (size_t)g);
		b = u32(f, f->loca + 4 * (size_t)g + 4);
	} else {
		a = 2 * (size_t)u16(f, f->loca + 2 * (size_t)g);
		b = 2 * (size_t)u16(f, f->loca + 2 * (size_t)g + 2);
	}
	if (b < a || b > f->glyf_len)
		return false;
	*off = f->glyf + a;
	*len = b - a;
	return true;
}

bool ttf_glyph_metrics(const struct ttf_font *f, unsigned g, struct ttf_metrics *m)
{
	memset(m, 0, sizeof *m);
	size_t off, len;
	if (!glyph_range(f, g, &off, &len))
		return false;
	unsigned h = g < f->nhmetrics ? g : f->nhmetrics - 1;
	m->advance = (int)u16(f, f->hmtx + 4 * (size_t)h);
	if (g < f->nhmetrics)
		m->lsb = s16(f, f->hmtx + 4 * (size_t)g + 2);
	else {
		/* Glyphs past the long metrics have only a side bearing. */
		size_t at = f->hmtx + 4 * (size_t)f->nhmetrics + 2 * (size_t)(g - f->nhmetrics);
		m->lsb = in_range(f, at, 2) && at + 2 <= f->hmtx + f->hmtx_len ? s16(f, at) : 0;
	}
	if (len == 0)
		return true;
	if (len < 10)
		return false;
	m->composite = s16(f, off) < 0;
	m->xmin = s16(f, off + 2);
	m->ymin = s16(f, off + 4);
	m->xmax = s16(f, off + 6);
	m->ymax = s16(f, off + 8);
	return true;
}

int ttf_kerning(const struct ttf_font *f, unsigned left, unsigned right)
{
	if (!f->npairs)
		return 0;
	uint32_t key = (uint32_t)left << 16 | right;
	unsigned lo = 0, hi = f->npairs;
	while (lo < hi) {
		unsigned mid = (lo + hi) / 2;
		uint32_t k = f->pairs[mid].key;
		if (k == key)
			return f->pairs[mid].value;
		if (k < key)
			lo = mid + 1;
		else
			hi = mid;
	}
	return 0;
}

/* ---- outlines ---- */

/* A glyph's points as the file gives them, composites flattened. */
struct points {
	double *x, *y;
	bool *on;
	unsigned *ends; /* the last point of each contour */
	size_t n, cap, nc, capc;
};

static void pts_push(struct points *P, double x, double y, bool on)
{
	if (P->n == P->cap) {
		P->cap = P->cap ? 2 * P->cap : 64;
		P->x = realloc(P->x, P->cap * sizeof *P->x);
		P->y = realloc(P->y, P->cap * sizeof *P->y);
		P->on = realloc(P->on, P->cap * sizeof *P->on);
		if (!P->x || !P->y || !P->on) abort();
	}
	P->x[P->n] = x;
	P->y[P->n] = y;
	P->on[P->n] = on;
	P->n++;
}

static void pts_free(struct points *P)
{
	free(P->x);
	free(P->y);
	free(P->on);
	free(P->ends);
}

/* One coordinate of a simple glyph's npts points, stored as deltas at *at
 * (flag short_bit: a byte, its sign by same_bit; else same_bit: no change;
 * else a signed 16-bit delta), summed into out. False if they run past end. */
static bool read_deltas(const struct ttf_font *f, size_t *at, size_t end, const unsigned char *flags,
                        unsigned npts, unsigned short_bit, unsigned same_bit, double *out)
{
	int v = 0;
	for (unsigned i = 0; i < npts; i++) {
		if (flags[i] & short_bit) {
			if (*at >= end)
				return false;
			int d = (int)u8(f, (*at)++);
			v += flags[i] & same_bit ? d : -d;
		} else if (!(flags[i] & same_bit)) {
			if (*at + 2 > end)
				return false;
			v += s16(f, *at);
			*at += 2;
		}
		out[i] = v;
	}
	return true;
}

/* A simple glyph (nc contours) at off, len bytes, appended to P. */
static bool read_simple(const struct ttf_font *f, size_t off, size_t len, unsigned nc, struct points *P)
{
	size_t end = off + len, at = off + 10;
	if (at + 2 * (size_t)nc + 2 > end)
		return false;
	size_t ends = at;
	unsigned npts = nc ? u16(f, ends + 2 * (size_t)(nc - 1)) + 1 : 0;
	for (unsigned i = 1; i < nc; i++)
		if (u16(f, ends + 2 * (size_t)i) < u16(f, ends + 2 * (size_t)(i - 1)))
			return false;
	at += 2 * (size_t)nc;
	at += 2 + u16(f, at); /* the instructions */
	if (at > end)
		return false;
	unsigned char *flags = malloc(npts ? npts : 1);
	if (!flags) abort();
	for (unsigned i = 0; i < npts;) {
		if (at >= end)
			goto bad;
		unsigned fl = u8(f, at++);
		flags[i++] = (unsigned char)fl;
		if (fl & PT_REPEAT) {
			if (at >= end)
				goto bad;
			unsigned r = u8(f, at++);
			if (r > npts - i)
				goto bad;
			while (r--)
				flags[i++] = (unsigned char)fl;
		}
	}
	size_t base = P->n;
	for (unsigned i = 0; i < npts; i++)
		pts_push(P, 0, 0, flags[i] & PT_ON_CURVE);
	if (!read_deltas(f, &at, end, flags, npts, PT_X_SHORT, PT_X_SAME, P->x + base) ||
	    !read_deltas(f, &at, end, flags, npts, PT_Y_SHORT, PT_Y_SAME, P->y + base))
		goto bad;
	free(flags);
	for (unsigned i = 0; i < nc; i++) {
		unsigned e = u16(f, ends + 2 * (size_t)i);
		if (P->nc == P->capc) {
			P->capc = P->capc ? 2 * P->capc : 16;
			P->ends = realloc(P->ends, P->capc * sizeof *P->ends);
			if (!P->ends) abort();
		}
		P->ends[P->nc++] = (unsigned)base + e;
	}
	return true;
bad:
	free(flags);
	return false;
}

static bool read_glyph(const struct ttf_font *f, unsigned g, struct points *P, int depth);

/* F2Dot14 at o. */
static double f2dot14(const struct ttf_font *f, size_t o)
{
	return s16(f, o) / 16384.0;
}

/* A composite glyph at off, len bytes: its components, transformed,
 * appended to P. */
static bool read_composite(const struct ttf_font *f, size_t off, size_t len, struct points *P, int depth)
{
	size_t end = off + len, at = off + 10;
	unsigned fl;
	do {
		if (at + 4 > end)
			return false;
		fl = u16(f, at);
		unsigned g = u16(f, at + 2);
		at += 4;
		int a1, a2;
		if (fl & CMP_ARGS_ARE_WORDS) {
			if (at + 4 > end)
				return false;
			a1 = s16(f, at);
			a2 = s16(f, at + 2);
			at += 4;
		} else {
			if (at + 2 > end)
				return false;
			a1 = (int8_t)u8(f, at);
			a2 = (int8_t)u8(f, at + 1);
			at += 2;
		}
		double m[4] = {1, 0, 0, 1}; /* x' = m0 x + m2 y, y' = m1 x + m3 y */
		if (fl & CMP_HAVE_SCALE) {
			if (at + 2 > end)
				return false;
			m[0] = m[3] = f2dot14(f, at);
			at += 2;
		} else if (fl & CMP_HAVE_XY_SCALE) {
			if (at + 4 > end)
				return false;
			m[0] = f2dot14(f, at);
			m[3] = f2dot14(f, at + 2);
			at += 4;
		} else if (fl & CMP_HAVE_2X2) {
			if (at + 8 > end)
				return false;
			for (int k = 0; k < 4; k++)
				m[k] = f2dot14(f, at + 2 * (size_t)k);
			at += 8;
		}
		size_t first = P->n;
		if (!read_glyph(f, g, P, depth + 1))
			return false;
		for (size_t i = first; i < P->n; i++) {
			double x = P->x[i], y = P->y[i];
			P->x[i] = m[0] * x + m[2] * y;
			P->y[i] = m[1] * x + m[3] * y;
		}
		double dx, dy;
		if (fl & CMP_ARGS_ARE_XY) {
			dx = a1;
			dy = a2;
		} else {
			/* Point matching: the component's point a2 lands on the
			 * point a1 of what came before. */
			size_t pa = (size_t)(unsigned)a1, pb = first + (size_t)(unsigned)a2;
			if (pa >= first || pb >= P->n)
				return false;
			dx = P->x[pa] - P->x[pb];
			dy = P->y[pa] - P->y[pb];
		}
		for (size_t i = first; i < P->n; i++) {
			P->x[i] += dx;
			P->y[i] += dy;
		}
	} while (fl & CMP_MORE);
	return true;
}

static bool read_glyph(const struct ttf_font *f, unsigned g, struct points *P, int depth)
{
	if (depth > MAX_COMPOSITE_DEPTH)
		return false;
	size_t off, len;
	if (!glyph_range(f, g, &off, &len))
		return false;
	if (len == 0)
		return true;
	if (len < 10)
		return false;
	int nc = s16(f, off);
	if (nc >= 0)
		return read_simple(f, off, len, (unsigned)nc, P);
	return read_composite(f, off, len, P, depth);
}

static void push_piece(struct ttf_outline *o, size_t *cap, double x0, double y0, double cx, double cy, double x1,
                       double y1, bool line)
{
	if (x0 == x1 && y0 == y1)
		return; /* a piece of no length: nothing to draw */
	if (o->n == *cap) {
		*cap = *cap ? 2 * *cap : 32;
		o->p = realloc(o->p, *cap * sizeof *o->p);
		if (!o->p) abort();
	}
	if (line) {
		cx = (x0 + x1) / 2;
		cy = (y0 + y1) / 2;
	}
	o->p[o->n++] = (struct ttf_piece){x0, y0, cx, cy, x1, y1, line};
}

/* The pieces of the contour of points [a, b] of P: two on-curve points in
 * a row are a line; an off-curve point between two on-curve points is a
 * curve's control point, and between two off-curve points lies an implied
 * on-curve point at their midpoint. */
static void contour_pieces(const struct points *P, size_t a, size_t b, struct ttf_outline *o, size_t *cap)
{
	size_t n = b - a + 1;
	if (n < 2)
		return;
	/* Start at an on-curve point, or at the midpoint of the first two
	 * off-curve ones. */
	size_t s = n;
	for (size_t i = 0; i < n; i++)
		if (P->on[a + i]) {
			s = i;
			break;
		}
	double sx, sy;
	if (s < n) {
		sx = P->x[a + s];
		sy = P->y[a + s];
	} else {
		sx = (P->x[a] + P->x[a + 1]) / 2;
		sy = (P->y[a] + P->y[a + 1]) / 2;
		/* The midpoint lies between points 0 and 1: begin at point 1. */
		s = 1;
		double px = sx, py = sy;
		bool have_ctrl = false;
		double qx = 0, qy = 0;
		for (size_t k = 0; k < n; k++) {
			size_t i = a + (s + k) % n;
			double x = P->x[i], y = P->y[i];
			if (have_ctrl) {
				double mx = (qx + x) / 2, my = (qy + y) / 2;
				push_piece(o, cap, px, py, qx, qy, mx, my, false);
				px = mx;
				py = my;
			}
			qx = x;
			qy = y;
			have_ctrl = true;
		}
		push_piece(o, cap, px, py, qx, qy, sx, sy, false);
		return;
	}
	double px = sx, py = sy, qx = 0, qy = 0;
	bool have_ctrl = false;
	for (size_t k = 1; k <= n; k++) {
		size_t i = a + (s + k) % n;
		double x = P->x[i], y = P->y[i];
		if (P->on[i]) {
			if (have_ctrl)
				push_piece(o, cap, px, py, qx, qy, x, y, false);
			else
				push_piece(o, cap, px, py, 0, 0, x, y, true);
			px = x;
			py = y;
			have_ctrl = false;
		} else {
			if (have_ctrl) {
				double mx = (qx + x) / 2, my = (qy + y) / 2;
				push_piece(o, cap, px, py, qx, qy, mx, my, false);
				px = mx;
				py = my;
			}
			qx = x;
			qy = y;
			have_ctrl = true;
		}
	}
}

bool ttf_glyph_outline(const struct ttf_font *f, unsigned g, struct ttf_outline *out)
{
	out->p = NULL;
	out->n = 0;
	struct points P = {0};
	if (!read_glyph(f, g, &P, 0)) {
		pts_free(&P);
		return false;
	}
	size_t cap = 0, a = 0;
	for (size_t c = 0; c < P.nc; c++) {
		size_t b = P.ends[c];
		if (b >= P.n || b + 1 < a) {
			pts_free(&P);
			ttf_outline_free(out);
			return false;
		}
		if (b + 1 > a)
			contour_pieces(&P, a, b, out, &cap);
		a = b + 1;
	}
	pts_free(&P);
	return true;
}

void ttf_outline_free(struct ttf_outline *o)
{
	free(o->p);
	o->p = NULL;
	o->n = 0;
}

struct ttf_shared_outline *ttf_glyph_shared(struct ttf_font *f, unsigned g)
{
	if (g >= f->nglyphs)
		return NULL;
	if (!f->shared) {
		f->shared = calloc(f->nglyphs, sizeof *f->shared);
		if (!f->shared) abort();
	}
	if (!f->shared[g]) {
		/* A damaged glyph is read again at each use: its text is an error. */
		struct ttf_outline ol;
		if (!ttf_glyph_outline(f, g, &ol))
			return NULL;
		struct ttf_shared_outline *s = malloc(sizeof *s);
		if (!s) abort();
		s->ol = ol;
		s->refs = 1; /* the font's */
		f->shared[g] = s;
	}
	return ttf_outline_ref(f->shared[g]);
}

struct ttf_shared_outline *ttf_outline_ref(struct ttf_shared_outline *s)
{
	if (s)
		s->refs++;
	return s;
}

void ttf_outline_release(struct ttf_shared_outline *s)
{
	if (s && --s->refs == 0) {
		ttf_outline_free(&s->ol);
		free(s);
	}
}

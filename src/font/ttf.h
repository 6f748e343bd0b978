/* ttf.h: a TrueType font reader, written from the TrueType specification:
 * the character map (cmap), glyph outlines (glyf and loca, simple and
 * composite glyphs), horizontal metrics (hhea, hmtx) and pair kerning
 * (kern, format 0). A TrueType collection (.ttc) gives its first font.
 * Every read is bounds-checked: a damaged file is an error, never a crash. */
#ifndef LUCENT_TTF_H
#define LUCENT_TTF_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct ttf_font;

/* One piece of a glyph's outline in font units: the quadratic Bezier curve
 * from (x0, y0) through the control point (cx, cy) to (x1, y1); a straight
 * piece has its control point at its midpoint and `line` set. Pieces of one
 * contour follow each other and the contour is closed. */
struct ttf_piece {
	double x0, y0, cx, cy, x1, y1;
	bool line;
};

/* A glyph's outline: n pieces (malloc'd; free with ttf_outline_free). */
struct ttf_outline {
	struct ttf_piece *p;
	size_t n;
};

/* A glyph's horizontal metrics in font units. */
struct ttf_metrics {
	int advance; /* advance width (hmtx) */
	int lsb;     /* left side bearing (hmtx) */
	int xmin, ymin, xmax, ymax; /* the glyph header's box; all 0 for an empty glyph */
	bool composite; /* made of other glyphs */
};

/* Load the font in the file at path. Returns it (free with ttf_free), or
 * NULL with a message in err[0..errlen) (the file cannot be read, is no
 * TrueType font, or a table it needs is missing or damaged). */
struct ttf_font *ttf_load(const char *path, char *err, size_t errlen);
/* The same from bytes in memory (copied). */
struct ttf_font *ttf_load_mem(const unsigned char *data, size_t size, char *err, size_t errlen);
void ttf_free(struct ttf_font *f);

/* Font units per em (the head table's unitsPerEm). */
unsigned ttf_units_per_em(const struct ttf_font *f);
/* A code with this bit set is looked up in the font's Macintosh (1, 0)
 * table, as POV-Ray does under charset ascii. */
#define TTF_MAC 0x80000000u
/* The glyph of Unicode code point c (0, the missing glyph, if the font has
 * none). A symbol font (a (3, 0) cmap) is looked up at c and at 0xF000 + c.
 * c | TTF_MAC is code c of the Macintosh table (0 without one). */
unsigned ttf_glyph_index(const struct ttf_font *f, uint32_t c);
/* Whether the font has a Macintosh (1, 0) table of format 0 or 6. */
bool ttf_has_mac_cmap(const struct ttf_font *f);
/* The metrics of glyph g; false if g is out of range or its data damaged. */
bool ttf_glyph_metrics(const struct ttf_font *f, unsigned g, struct ttf_metrics *m);
/* The kerning between glyphs left and right in font units (the first
 * horizontal format-0 kern subtable; 0 when there is none). */
int ttf_kerning(const struct ttf_font *f, unsigned left, unsigned right);
/* The outline of glyph g into *out (empty for a glyph with no contours);
 * false if its data is damaged (out is then empty). */
bool ttf_glyph_outline(const struct ttf_font *f, unsigned g, struct ttf_outline *out);
void ttf_outline_free(struct ttf_outline *o);

/* A glyph's outline read once per font and shared by its users (the text
 * objects made from it), each holding a reference; it outlives the font. */
struct ttf_shared_outline {
	struct ttf_outline ol;
	unsigned refs;
};
/* Glyph g's outline, read on its first use and kept by the font (f is
 * changed only in that cache): a new reference, or NULL if its data is
 * damaged. */
struct ttf_shared_outline *ttf_glyph_shared(struct ttf_font *f, unsigned g);
/* A new reference to s, and the release of one (the last frees it). */
struct ttf_shared_outline *ttf_outline_ref(struct ttf_shared_outline *s);
void ttf_outline_release(struct ttf_shared_outline *s);

#endif

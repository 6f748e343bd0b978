/* test_text.c: unit tests for the TrueType reader (src/font/ttf.c) and the
 * text object (src/geom/text.c), against what POV-Ray 3.7 prints for its
 * own fonts (Debian's fonts-povray, /usr/share/fonts/truetype/povray).
 * The expected values were printed by POV-Ray 3.7.0.10 with
 *   #declare T = text { ttf "timrom.ttf" "AV" 1, 0 }
 *   #debug concat(vstr(3, min_extent(T), ",", 0, 8), ...)
 * and trace(T, from, dir, N). POV-Ray's own figures carry a fuzz of about
 * 2e-5 (its bounds are a little larger than the outlines, and its hit
 * points and normals lean as if the text were turned by 0.001 degrees:
 * normals have 1.745e-5 = sin(0.001 deg) components), hence the tolerances.
 * The tests skip when POV-Ray's fonts are not installed. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "font/ttf.h"
#include "geom/shapes.h"
#include "scene/object.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};
static const char FONTS[] = "/usr/share/fonts/truetype/povray/";

/* POV-Ray's font `name`, or a skipped test when it is not installed. */
static struct ttf_font *font(const char *name)
{
	char path[256], err[200];
	snprintf(path, sizeof path, "%s%s", FONTS, name);
	if (access(path, R_OK) != 0)
		return NULL;
	struct ttf_font *f = ttf_load(path, err, sizeof err);
	if (!f)
		fail_msg("%s: %s", path, err);
	return f;
}

#define NEED_FONT(f, name)                                  \
	struct ttf_font *f = font(name);                    \
	do {                                                \
		if (!f) {                                   \
			skip();                             \
			return;                             \
		}                                           \
	} while (0)

static struct object *text(struct ttf_font *f, const char *s, double thick, double ox, double oy)
{
	uint32_t codes[64];
	size_t n = strlen(s);
	assert_true(n < 64);
	for (size_t i = 0; i < n; i++)
		codes[i] = (unsigned char)s[i];
	uint32_t bad = 1;
	struct object *o = text_new(f, codes, n, thick, ox, oy, nopos, &bad);
	assert_int_equal(bad, 0);
	object_prepare(o);
	return o;
}

#define assert_extent(o, x0, y0, z0, x1, y1, z1)                          \
	do {                                                              \
		struct aabb bx_ = object_world_bounds(o);                 \
		assert_vec_near(bx_.lo, x0, y0, z0, 5e-5);                 \
		assert_vec_near(bx_.hi, x1, y1, z1, 5e-5);                 \
	} while (0)

/* ---- the reader ---- */

static void test_ttf_tables(void **state)
{
	(void)state;
	NEED_FONT(f, "timrom.ttf");
	assert_int_equal(ttf_units_per_em(f), 1000);
	unsigned a = ttf_glyph_index(f, 'A'), v = ttf_glyph_index(f, 'V');
	assert_int_equal(a, 34);
	assert_int_equal(v, 55);
	struct ttf_metrics m;
	assert_true(ttf_glyph_metrics(f, a, &m));
	assert_int_equal(m.advance, 750);
	assert_int_equal(m.lsb, 6);
	/* The kern table of timrom.ttf is not sorted: VA comes after AV. */
	assert_int_equal(ttf_kerning(f, a, v), -187);
	assert_int_equal(ttf_kerning(f, v, a), -150);
	assert_int_equal(ttf_kerning(f, a, a), 0);
	/* A character the font lacks is the missing glyph. */
	assert_int_equal(ttf_glyph_index(f, 0xE9), 0);
	struct ttf_outline o;
	assert_true(ttf_glyph_outline(f, a, &o));
	assert_int_equal(o.n, 27);
	ttf_outline_free(&o);
	ttf_free(f);
}

static void test_ttf_damaged(void **state)
{
	(void)state;
	char err[200];
	static const unsigned char junk[] = "not a font at all, not even close";
	assert_null(ttf_load_mem(junk, sizeof junk, err, sizeof err));
	assert_string_equal(err, "it is not a TrueType font");
	static const unsigned char otto[16] = {'O', 'T', 'T', 'O'};
	assert_null(ttf_load_mem(otto, sizeof otto, err, sizeof err));
	assert_non_null(strstr(err, "CFF"));
	/* A true font cut short anywhere never crashes the reader. */
	FILE *fp = fopen("/usr/share/fonts/truetype/povray/timrom.ttf", "rb");
	if (!fp) {
		skip();
		return;
	}
	static unsigned char buf[40000];
	size_t n = fread(buf, 1, sizeof buf, fp);
	fclose(fp);
	for (size_t cut = 0; cut < n; cut += 997) {
		struct ttf_font *f = ttf_load_mem(buf, cut, err, sizeof err);
		if (!f)
			continue;
		struct ttf_outline o;
		struct ttf_metrics m;
		for (unsigned g = 0; g < 150; g++) {
			ttf_glyph_metrics(f, g, &m);
			if (ttf_glyph_outline(f, g, &o))
				ttf_outline_free(&o);
		}
		ttf_free(f);
	}
}

/* ---- layout: min_extent and max_extent as POV-Ray prints them ---- */

static void test_text_extents(void **state)
{
	(void)state;
	NEED_FONT(f, "timrom.ttf");
	struct object *o;
	o = text(f, "A", 1, 0, 0);
	assert_extent(o, -0.00001215, -0.00001745, -0.00001385, 0.73601747, 0.69601279, 1.00001323);
	object_free(o);
	o = text(f, "AV", 1, 0, 0);
	assert_extent(o, -0.00001215, -0.01601745, -0.00002358, 1.27801776, 0.69602227, 1.00001311);
	object_free(o);
	o = text(f, "VA", 1, 0, 0);
	assert_extent(o, -0.00001215, -0.01601745, -0.00002425, 1.31601775, 0.69602293, 1.00001323);
	object_free(o);
	o = text(f, "Wa", 1, 0, 0);
	assert_extent(o, -0.00001187, -0.01601745, -0.00002509, 1.36401772, 0.68002379, 1.00001299);
	object_free(o);
	o = text(f, "Ho", 1, 0, 0);
	assert_extent(o, -0.00001187, -0.01001745, -0.00002221, 1.20501757, 0.68002105, 1.00001287);
	object_free(o);
	o = text(f, "g", 1, 0, 0);
	assert_extent(o, -0.00000819, -0.21201745, -0.00001262, 0.45402113, 0.46900794, 1.00000918);
	object_free(o);
	/* Spaces: their pen positions count. */
	o = text(f, "H  ", 1, 0, 0);
	assert_extent(o, -0.00001, -0.00002, -0.00002, 0.98502, 0.68002, 1.00001);
	object_free(o);
	o = text(f, "  ", 1, 0, 0);
	assert_extent(o, -0.00000, -0.00002, -0.00001, 0.25402, 0.00000, 1.00000);
	object_free(o);
	/* Offset <0.1, 0.2> after each character. */
	o = text(f, "AV", 1, 0.1, 0.2);
	assert_extent(o, -0.00001536, -0.00001745, -0.00002505, 1.37801743, 0.88002402, 1.00001645);
	object_free(o);
	/* A negative thickness extrudes towards -z. */
	o = text(f, "A", -1, 0, 0);
	assert_extent(o, -0.00002960, 0.00000000, -1.00001180, 0.73600000, 0.69603026, 0.00001121);
	object_free(o);
	/* No characters: unbounded (POV-Ray prints +-1e10). */
	o = text(f, "", 1, 0, 0);
	struct aabb b = object_world_bounds(o);
	assert_true(isinf(b.lo.x) && isinf(b.hi.y));
	object_free(o);
	ttf_free(f);
}

static void test_text_other_fonts(void **state)
{
	(void)state;
	/* crystal.ttf has 2048 units per em; povlogo.ttf 512, a symbol cmap
	 * and glyphs whose xMin is not their left side bearing. */
	NEED_FONT(c, "crystal.ttf");
	struct object *o = text(c, "AV", 1, 0, 0);
	assert_extent(o, -0.00001185, -0.00197058, -0.00001711, 0.92091590, 0.67921525, 1.00001287);
	object_free(o);
	ttf_free(c);
	NEED_FONT(y, "cyrvetic.ttf");
	o = text(y, "AV", 1, 0, 0);
	assert_extent(o, -0.00001271, -0.00001745, -0.00002173, 1.18801749, 0.72802073, 1.00001383);
	object_free(o);
	ttf_free(y);
	NEED_FONT(l, "povlogo.ttf");
	o = text(l, "AB", 1, 0, 0);
	assert_extent(o, -0.00001749, 0.00193567, -0.00003011, 1.66993928, 1.00198233, 1.00001848);
	object_free(o);
	ttf_free(l);
}

/* ---- trace() and inside() ---- */

/* The hit of the ray org + t dir: its point and raw (object) normal as
 * POV-Ray's trace() gives them. */
static void assert_trace(const struct object *o, vec3 org, vec3 dir, vec3 pt, vec3 n)
{
	struct hit h = must_hit(o, org, dir, 0);
	vec3 p = v3_madd(org, dir, h.t);
	assert_vec_near(p, pt.x, pt.y, pt.z, 5e-5);
	vec3 nn = object_normal(o, p, &h);
	assert_vec_near(nn, n.x, n.y, n.z, 1e-3);
}

static void test_text_trace(void **state)
{
	(void)state;
	NEED_FONT(f, "timrom.ttf");
	struct object *o = text(f, "H", 1, 0, 0);
	/* The caps: z = 0 gives -z, z = thickness +z. */
	assert_trace(o, v3(0.1, 0.3, -1), v3(0, 0, 1), v3(0.1, 0.3, 0.00000349), v3(0, 0, -1));
	assert_trace(o, v3(0.1, 0.3, 2), v3(0, 0, -1), v3(0.1, 0.3, 1.00000349), v3(0, 0, 1));
	assert_trace(o, v3(0.1, 0.3, 0.5), v3(0, 0, -1), v3(0.1, 0.3, 0.00000349), v3(0, 0, -1));
	/* A side from inside the stem: the normal points right of the
	 * outline's travel (here -x, into the stem). */
	assert_trace(o, v3(0.1, 0.3, 0.5), v3(1, 0, 0), v3(0.20000349, 0.3, 0.5), v3(-1, 0, 0));
	assert_trace(o, v3(0.05, 2, 0.5), v3(0, -1, 0), v3(0.05, 0.67999215, 0.5), v3(0, -1, 0));
	assert_trace(o, v3(0.05, -1, 0.5), v3(0, 1, 0), v3(0.05, -0.00000785, 0.5), v3(0, 1, 0));
	/* inside(T, <0.1,0.3,0.5>), <0.1,0.3,1.5>, <0.05,0.3,0.5>: 1 0 0. */
	assert_true(object_inside(o, v3(0.1, 0.3, 0.5)));
	assert_false(object_inside(o, v3(0.1, 0.3, 1.5)));
	assert_false(object_inside(o, v3(0.05, 0.3, 0.5)));
	/* Along x through both stems: four crossings, in order. */
	struct ray r = mkray(v3(-1, 0.3, 0.5), v3(1, 0, 0));
	struct hit hs[8];
	int n = o->ops->all_hits(o, &r, 0, INFINITY, hs, 8);
	assert_int_equal(n, 4);
	for (int i = 1; i < n; i++)
		assert_true(hs[i].t > hs[i - 1].t);
	object_free(o);

	/* With a negative thickness the cap at z = 0 still gives -z. */
	o = text(f, "H", -1, 0, 0);
	assert_trace(o, v3(0.1, 0.3, -2), v3(0, 0, 1), v3(0.1, 0.3, -0.99999651), v3(0, 0, 1));
	assert_trace(o, v3(0.1, 0.3, 2), v3(0, 0, -1), v3(0.1, 0.3, 0.00000349), v3(0, 0, -1));
	object_free(o);

	o = text(f, "A", 1, 0, 0);
	assert_trace(o, v3(-1, 0.005, 0.5), v3(1, 0, 0), v3(0.00000864, 0.005, 0.5), v3(1, 0, 0));
	assert_trace(o, v3(2, 0.005, 0.5), v3(-1, 0, 0), v3(0.73600864, 0.005, 0.5), v3(-1, 0, 0));
	object_free(o);

	/* text { ttf "timrom.ttf" "Wag" 0.5, <0.05, -0.1, 0> rotate 10*y }:
	 * curves, an offset and a transform. */
	o = text(f, "Wag", 0.5, 0.05, -0.1);
	transform(o, xform_rotate(v3(0, 10, 0)));
	object_prepare(o);
	assert_trace(o, v3(-1, 0.2, 0.2), v3(1, 0, 0), v3(0.26342705, 0.2, 0.2), v3(0.92720609, 0.33698058, -0.16350216));
	assert_trace(o, v3(0.2, 0.2, -1), v3(0.1, 0, 1), v3(0.29480167, 0.2, -0.05198325),
	             v3(-0.17366537, 0.00001745, -0.98480472));
	assert_trace(o, v3(0.7, 0.2, -1), v3(0.1, 0.1, 1), v3(0.81859863, 0.31859863, 0.18598629),
	             v3(-0.93230154, 0.32215277, 0.16441240));
	assert_trace(o, v3(1.2, 2, 0.2), v3(0, -1, 0), v3(1.2, 0.36525510, 0.2), v3(0.16836675, -0.98527664, -0.02970809));
	/* A grazing hit on the g's bowl: POV-Ray's 0.001-degree lean moves it
	 * along the ray by 2.6e-4. */
	struct hit h = must_hit(o, v3(1.2, -0.15, -1), v3(-0.1, 0.05, 1), 0);
	vec3 p = v3_madd(v3(1.2, -0.15, -1), v3(-0.1, 0.05, 1), h.t);
	assert_vec_near(p, 1.11828207, -0.10914103, -0.18282068, 3e-4);
	assert_true(object_inside(o, v3(0.78, 0.2, 0.25)));
	assert_false(object_inside(o, v3(0.1, 0.3, 0.25)));
	assert_false(object_inside(o, v3(1.3, -0.1, 0.1)));
	object_free(o);
	ttf_free(f);
}

/* Composite glyphs (accented letters) in DejaVuSans, a system font (the
 * test skips without it). Expected values: POV-Ray 3.7 with charset utf8,
 * `text { ttf "DejaVuSans.ttf" S 1, 0 }`, min_extent and max_extent printed
 * with vstr(3, ..., 8), and trace() from <-1, 0.28, 0.5> along +x (its normal as POV-Ray gives it). */
static void test_text_composite(void **state)
{
	(void)state;
	static const char path[] = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
	char err[200];
	if (access(path, R_OK) != 0) {
		skip();
		return;
	}
	struct ttf_font *f = ttf_load(path, err, sizeof err);
	if (!f)
		fail_msg("%s: %s", path, err);
	struct object *o;
	o = text(f, "e", 1, 0, 0);
	assert_extent(o, -0.00001, -0.01418, -0.00001, 0.50685, 0.56007, 1.00001);
	object_free(o);
	/* e acute: drawn 113 units (its xMin) right of where a simple "e"
	 * is, the bounds still from x = 0. */
	o = text(f, "\xe9", 1, 0, 0);
	assert_extent(o, -0.00001, -0.01418, -0.00001, 0.56203, 0.79981, 1.00001);
	assert_trace(o, v3(-1, 0.28, 0.5), v3(1, 0, 0), v3(0.05533, 0.28, 0.5), v3(0.99970, -0.02467, 0));
	object_free(o);
	o = text(f, "\xe9X", 1, 0, 0);
	assert_extent(o, -0.00001396, -0.01417761, -0.00002243, 1.21388495, 0.79982585, 1.00001502);
	object_free(o);
	o = text(f, "X\xe9", 1, 0, 0);
	assert_extent(o, -0.00001396, -0.01417761, -0.00002267, 1.22755682, 0.79982609, 1.00001502);
	object_free(o);
	/* E grave (xMin 201); i diaeresis has xMin -12 and is placed as a
	 * simple glyph is. */
	o = text(f, "\xc8", 1, 0, 0);
	assert_extent(o, -0.00002, -0.00002, -0.00001, 0.56789, 0.92726, 1.00002);
	object_free(o);
	o = text(f, "\xef", 1, 0, 0);
	assert_extent(o, -0.00001323, -0.00001745, -0.00000606, 0.29005650, 0.75781757, 1.00001419);
	object_free(o);
	ttf_free(f);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_ttf_tables),
		cmocka_unit_test(test_ttf_damaged),
		cmocka_unit_test(test_text_extents),
		cmocka_unit_test(test_text_other_fonts),
		cmocka_unit_test(test_text_trace),
		cmocka_unit_test(test_text_composite),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

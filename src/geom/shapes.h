/* shapes.h: constructors for the primitives in src/geom/, the part of the
 * builder API that makes objects. Each returns a new object (caller owns it;
 * free with object_free) with no texture and the identity transform. */
#ifndef LUCENT_SHAPES_H
#define LUCENT_SHAPES_H

#include "scene/object.h"

#include <stddef.h>
#include <stdint.h>

struct object *sphere_new(vec3 center, double radius, struct srcpos pos);
/* plane { normal, distance }: the points p with dot(p, n̂) = distance*|n|/|n|
 * as POV-Ray defines it; the inside is the side the normal points away from. */
struct object *plane_new(vec3 normal, double distance, struct srcpos pos);
/* box { corner1, corner2 } in any order. */
struct object *box_new(vec3 c1, vec3 c2, struct srcpos pos);

/* cylinder { base, cap, radius [open] }. */
struct object *cylinder_new(vec3 base, vec3 cap, double radius, bool open, struct srcpos pos);
/* cone { base, base_radius, cap, cap_radius [open] }. */
struct object *cone_new(vec3 base, double r0, vec3 cap, double r1, bool open, struct srcpos pos);
/* disc { center, normal, radius [, hole_radius] }. */
struct object *disc_new(vec3 center, vec3 normal, double radius, double hole, struct srcpos pos);
/* torus { major, minor [sturm] }, in the xz plane around the y axis. */
struct object *torus_new(double major, double minor, bool sturm, struct srcpos pos);
/* quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }:
 * A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0. */
struct object *quadric_new(vec3 abc, vec3 def, vec3 ghi, double j, struct srcpos pos);
/* poly { order, <coefficients> } for order 2..7, and cubic (3) and quartic
 * (4): coef has (order+1)(order+2)(order+3)/6 entries in POV-Ray's order. */
struct object *poly_new(int order, const double *coef, bool sturm, struct srcpos pos);
/* superellipsoid { <e, n> }. */
struct object *superellipsoid_new(double e, double n, struct srcpos pos);
/* triangle { a, b, c } and smooth_triangle { a, na, b, nb, c, nc }. */
struct object *triangle_new(vec3 a, vec3 b, vec3 c, struct srcpos pos);
struct object *smooth_triangle_new(vec3 a, vec3 na, vec3 b, vec3 nb, vec3 c, vec3 nc, struct srcpos pos);

/* prism { spline sweep h1, h2, n, points }: the n 2-D points (x, z) cut
 * into closed sub-prisms by the spline's rules (doc/objects.md). What was
 * wrong with the points goes to *rep (may be NULL): the parser turns it
 * into warnings, or an error when rep->open_at >= 0 (the prism is then
 * empty). */
enum prism_spline { PRISM_LINEAR_SPLINE, PRISM_QUADRATIC_SPLINE, PRISM_CUBIC_SPLINE, PRISM_BEZIER_SPLINE };
struct prism_report {
	bool closed_last; /* linear: the last sub-prism was not closed; it was closed */
	int dropped;      /* bezier: sub-prisms that broke off or never closed, left out */
	int open_at;      /* quadratic, cubic: the first point of a sub-prism that
	                   * does not close, or -1 */
};
struct object *prism_new(enum prism_spline spline, bool conic, double h1, double h2, const double (*pts)[2], int n,
                         struct srcpos pos, struct prism_report *rep);
/* The prism's `open` (no caps) and `sturm` (the Sturm root solver). */
void prism_set_open(struct object *o, bool open);
void prism_set_sturm(struct object *o, bool sturm);

/* text { ttf FONT STRING thickness, offset }: the glyphs of codes[0..n)
 * (Unicode code points) laid out as POV-Ray 3.7 does (see text.c) and
 * extruded from z = 0 to z = thickness. The font stays the caller's; the
 * text shares the glyph outlines the font keeps (ttf_glyph_shared), which
 * outlive it. A glyph whose data is damaged is left out and its code
 * point (or 0xFFFFFFFF for code 0) goes to *bad_glyph (may be NULL; 0 if
 * every glyph was read). */
struct ttf_font;
struct object *text_new(struct ttf_font *font, const uint32_t *codes, size_t n, double thickness, double off_x,
                        double off_y, struct srcpos pos, uint32_t *bad_glyph);

#endif

/* objects2.c: the arguments of the object statements polygon, lathe, sor and
 * isosurface, with POV-Ray's rules for their counts and points (measured
 * where the manual is silent: a point may be a float f, meaning <f, f>; a
 * count is truncated; isosurface items come before the object
 * modifiers), and their `open` and `sturm` modifiers. The shapes are in
 * src/geom/polygon.c, lathe.c, sor.c and isosurface.c. */
#include "geom/shapes2.h"
#include "lang/parser.h"
#include "scene/fn.h"

#include <math.h>
#include <stdlib.h>

static void opt_comma(struct parser *p)
{
	parse_accept(p, TOK_COMMA);
}

/* The count of points at the current token, truncated, at least min
 * (what = the object, for the message). */
static int point_count(struct parser *p, int min, const char *what, const char *spline)
{
	struct srcpos at = parse_peek(p)->pos;
	double count = trunc(parse_float(p));
	if (!(count >= min))
		parse_error_at(p, at, "a %s%s%s needs at least %d points, found %g", spline ? spline : "",
		               spline ? " " : "", what, min, count);
	if (count > 1e7)
		parse_error_at(p, at, "a %s has at most 10000000 points, found %g", what, count);
	return (int)count;
}

struct points {
	void *pt;
	struct srcpos *pos;
};

static void free_points_cb(void *v)
{
	struct points *pp = v;
	free(pp->pt);
	free(pp->pos);
	free(pp);
}

static struct points *new_points(struct parser *p, int n, size_t size, int *slot)
{
	struct points *pp = calloc(1, sizeof *pp);
	if (!pp) abort();
	*slot = parse_own(p, pp, free_points_cb);
	pp->pt = malloc((size_t)n * size);
	pp->pos = malloc((size_t)n * sizeof *pp->pos);
	if (!pp->pt || !pp->pos) abort();
	return pp;
}

static const char *vector_kind(const struct value *v)
{
	if (v->kind != VAL_VECTOR)
		return val_kind_name(v->kind);
	return v->n == 2 ? "a 2-D vector" : v->n == 3 ? "a 3-D vector" : v->n == 4 ? "a 4-D vector" : "a 5-D vector";
}

/* n 2-D points (a float f is <f, f>), commas optional, into pt. */
static void read_points_2d(struct parser *p, int n, double (*pt)[2], struct srcpos *pos, const char *what)
{
	for (int i = 0; i < n; i++) {
		opt_comma(p);
		struct srcpos vat = parse_peek(p)->pos;
		struct value v = parse_expression(p);
		if (v.kind == VAL_FLOAT)
			v.v[1] = v.v[0];
		else if (v.kind != VAL_VECTOR || v.n != 2)
			parse_error_at(p, vat, "a %s point is a 2-D vector, found %s", what, vector_kind(&v));
		pt[i][0] = v.v[0];
		pt[i][1] = v.v[1];
		pos[i] = vat;
	}
}

/* polygon '{' FLOAT ',' POINT { ',' POINT } ... (POINT a 2-D vector, z = 0,
 * or a 3-D one; a float f is <f, f, f>). */
static struct object *parse_polygon(struct parser *p, struct srcpos at)
{
	int n = point_count(p, 3, "polygon", NULL);
	int slot;
	struct points *pp = new_points(p, n, sizeof(vec3), &slot);
	vec3 *pt = pp->pt;
	for (int i = 0; i < n; i++) {
		opt_comma(p);
		struct srcpos vat = parse_peek(p)->pos;
		struct value v = parse_expression(p);
		if (v.kind == VAL_FLOAT)
			pt[i] = v3(v.v[0], v.v[0], v.v[0]);
		else if (v.kind == VAL_VECTOR && (v.n == 2 || v.n == 3))
			pt[i] = v3(v.v[0], v.v[1], v.n == 3 ? v.v[2] : 0);
		else
			parse_error_at(p, vat, "a polygon point is a 2-D or 3-D vector, found %s", vector_kind(&v));
		pp->pos[i] = vat;
	}
	bool closed_last, nonplanar;
	struct object *o = polygon_new(pt, n, at, &closed_last, &nonplanar);
	if (nonplanar)
		parse_warning_at(p, at, "the points of this polygon are not in one plane: it is never seen (as in POV-Ray)");
	if (closed_last)
		parse_warning_at(p, at, "the last sub-polygon of this polygon is not closed: closing it");
	parse_release(p, slot);
	free_points_cb(pp);
	return o;
}

static const char *const lathe_spline_names[] = {"linear_spline", "quadratic_spline", "cubic_spline",
                                                 "bezier_spline"};

/* lathe '{' [linear_spline | quadratic_spline | cubic_spline | bezier_spline]
 *   FLOAT ',' POINT { ',' POINT } ... (the points <r, y>, r >= 0). */
static struct object *parse_lathe(struct parser *p, struct srcpos at)
{
	enum lathe_spline spline = LATHE_LINEAR_SPLINE;
	for (;;) {
		if (parse_accept_kw(p, KW_LINEAR_SPLINE)) spline = LATHE_LINEAR_SPLINE;
		else if (parse_accept_kw(p, KW_QUADRATIC_SPLINE)) spline = LATHE_QUADRATIC_SPLINE;
		else if (parse_accept_kw(p, KW_CUBIC_SPLINE)) spline = LATHE_CUBIC_SPLINE;
		else if (parse_accept_kw(p, KW_BEZIER_SPLINE)) spline = LATHE_BEZIER_SPLINE;
		else break;
	}
	static const int min_points[] = {2, 3, 4, 4};
	struct srcpos nat = parse_peek(p)->pos;
	int n = point_count(p, min_points[spline], "lathe", lathe_spline_names[spline]);
	if (spline == LATHE_BEZIER_SPLINE && n % 4 != 0)
		parse_error_at(p, nat, "a bezier_spline lathe needs four points per piece, found %d points", n);
	int slot;
	struct points *pp = new_points(p, n, sizeof(double[2]), &slot);
	double (*pt)[2] = pp->pt;
	read_points_2d(p, n, pt, pp->pos, "lathe");
	for (int i = 0; i < n; i++)
		if (pt[i][0] < 0)
			parse_error_at(p, pp->pos[i], "a lathe point's radius (its first component) cannot be negative, "
			               "found %g", pt[i][0]);
	struct object *o = lathe_new(spline, (const double (*)[2])pt, n, at);
	parse_release(p, slot);
	free_points_cb(pp);
	return o;
}

/* sor '{' FLOAT ',' POINT { ',' POINT } ... (the points <r, y>, r >= 0,
 * the heights of the second to the last but one increasing). */
static struct object *parse_sor(struct parser *p, struct srcpos at)
{
	int n = point_count(p, 4, "sor", NULL);
	int slot;
	struct points *pp = new_points(p, n, sizeof(double[2]), &slot);
	double (*pt)[2] = pp->pt;
	read_points_2d(p, n, pt, pp->pos, "sor");
	for (int i = 0; i < n; i++)
		if (pt[i][0] < 0)
			parse_error_at(p, pp->pos[i], "a sor point's radius (its first component) cannot be negative, "
			               "found %g", pt[i][0]);
	int bad = sor_check((const double (*)[2])pt, n);
	if (bad >= 0)
		parse_error_at(p, pp->pos[bad], "the heights of a sor's points must increase from the second point to "
		               "the last but one: %g follows %g", pt[bad][1], pt[bad - 1][1]);
	struct object *o = sor_new((const double (*)[2])pt, n, at);
	parse_release(p, slot);
	free_points_cb(pp);
	return o;
}

static void free_object_cb(void *o)
{
	object_free(o);
}

/* isosurface '{' function '{' ... '}' { iso_item } ...
 * iso_item := contained_by '{' (box '{' V ',' V '}' | sphere '{' V ',' F '}') '}'
 *           | threshold F | accuracy F | max_gradient F | evaluate F ',' F ',' F
 *           | open | max_trace F | all_intersections
 * The items come before the object modifiers, as in POV-Ray. */
static struct object *parse_isosurface(struct parser *p, struct srcpos at)
{
	if (!parse_is_kw(p, KW_FUNCTION))
		parse_expected(p, "'function' (an isosurface begins with its function)");
	struct fn *f = parse_function(p);
	if (f->nparams > 3 || fn_is_vector(f)) {
		fn_unref(f);
		parse_error_at(p, at, "an isosurface's function takes x, y and z and has one value");
	}
	struct object *o = isosurface_new(f, at);
	fn_unref(f);
	int slot = parse_own(p, o, free_object_cb);
	for (;;) {
		struct srcpos iat = parse_peek(p)->pos;
		if (parse_accept_kw(p, KW_CONTAINED_BY)) {
			parse_expect(p, TOK_LBRACE);
			if (parse_accept_kw(p, KW_BOX)) {
				parse_expect(p, TOK_LBRACE);
				vec3 a = parse_vector(p);
				opt_comma(p);
				vec3 b = parse_vector(p);
				parse_expect(p, TOK_RBRACE);
				isosurface_set_box(o, a, b);
			} else if (parse_accept_kw(p, KW_SPHERE)) {
				parse_expect(p, TOK_LBRACE);
				vec3 c = parse_vector(p);
				opt_comma(p);
				double r = parse_float(p);
				parse_expect(p, TOK_RBRACE);
				isosurface_set_sphere(o, c, r);
			} else {
				parse_expected(p, "box or sphere (the only containers of an isosurface)");
			}
			parse_expect(p, TOK_RBRACE);
		} else if (parse_accept_kw(p, KW_THRESHOLD)) {
			isosurface_set_threshold(o, parse_float(p));
		} else if (parse_accept_kw(p, KW_ACCURACY)) {
			double a = parse_float(p);
			if (!(a > 0)) {
				parse_warning_at(p, iat, "isosurface accuracy %g is not positive: using 0.001", a);
				a = 0.001;
			}
			isosurface_set_accuracy(o, a);
		} else if (parse_accept_kw(p, KW_MAX_GRADIENT)) {
			double g = parse_float(p);
			if (!(g > 0)) {
				parse_warning_at(p, iat, "isosurface max_gradient %g is not positive: using 1.1", g);
				g = 1.1;
			}
			isosurface_set_max_gradient(o, g);
		} else if (parse_accept_kw(p, KW_EVALUATE)) {
			double e0 = parse_float(p);
			opt_comma(p);
			double e1 = parse_float(p);
			opt_comma(p);
			double e2 = parse_float(p);
			isosurface_set_evaluate(o, e0, e1, e2);
		} else if (parse_accept_kw(p, KW_OPEN)) {
			bool on = true;
			if (parse_starts_expression(p))
				on = parse_float(p) != 0;
			isosurface_set_open(o, on);
		} else if (parse_accept_kw(p, KW_MAX_TRACE)) {
			double m = trunc(parse_float(p));
			if (!(m >= 1)) {
				parse_warning_at(p, iat, "isosurface max_trace %g is not positive: using 1", m);
				m = 1;
			}
			isosurface_set_max_trace(o, m > 1e6 ? 1000000 : (int)m);
		} else if (parse_accept_kw(p, KW_ALL_INTERSECTIONS)) {
			isosurface_set_max_trace(o, 0);
		} else {
			break;
		}
	}
	parse_release(p, slot);
	return o;
}

bool parse_is_object2(enum kw k)
{
	return k == KW_POLYGON || k == KW_LATHE || k == KW_SOR || k == KW_ISOSURFACE;
}

struct object *parse_object2(struct parser *p, enum kw k, struct srcpos at)
{
	switch (k) {
	case KW_POLYGON: return parse_polygon(p, at);
	case KW_LATHE: return parse_lathe(p, at);
	case KW_SOR: return parse_sor(p, at);
	default: return parse_isosurface(p, at);
	}
}

bool parse_object2_flag(struct object *o, enum kw k, bool is_open, bool on)
{
	if (k == KW_SOR) {
		if (is_open)
			sor_set_open(o, on);
		else
			sor_set_sturm(o, on);
		return true;
	}
	if (k == KW_LATHE && !is_open) {
		lathe_set_sturm(o, on);
		return true;
	}
	return false;
}

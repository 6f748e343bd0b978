/* builtin.c: the language's built-in functions (float, vector and string
 * functions of POV-Ray 3.7's manual). Each parses its own parenthesised
 * arguments; the current token is the function's keyword. */
#include "lang/parser.h"

#include "geom/csg.h"
#include "lang/intern.h"
#include "lang/ustr.h"
#include "math/mat.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* ---- arguments ---- */

static struct value arg(struct parser *p) { return parse_expression(p); }

static double arg_float(struct parser *p, const char *fn)
{
	struct value v = arg(p);
	parse_need_float(p, &v, fn);
	return v.v[0];
}

static vec3 arg_vec3(struct parser *p, const char *fn)
{
	struct value v = arg(p);
	parse_need_numeric(p, &v, fn);
	if (v.kind == VAL_COLOR)
		parse_error_at(p, v.pos, "%s needs a vector, not a color", fn);
	val_widen(&v, 3);
	return v3(v.v[0], v.v[1], v.v[2]);
}

static const char *arg_string(struct parser *p, const char *fn)
{
	struct srcpos at = parse_peek(p)->pos;
	struct value v = arg(p);
	if (v.kind != VAL_STRING) {
		const char *kind = val_kind_name(v.kind);
		parse_drop(p, &v);
		parse_error_at(p, at, "%s needs a string, not a %s", fn, kind);
	}
	return v.str;
}

static void comma(struct parser *p) { parse_expect(p, TOK_COMMA); }
static void lparen(struct parser *p) { parse_expect(p, TOK_LPAREN); }
static void rparen(struct parser *p) { parse_expect(p, TOK_RPAREN); }

static struct value str_value(struct parser *p, const char *s, size_t n, struct srcpos at)
{
	struct value v = {.kind = VAL_STRING, .pos = at, .str = parse_intern(p, s, n)};
	return v;
}

static struct value vec3_value(vec3 r, struct srcpos at)
{
	double c[3] = {r.x, r.y, r.z};
	return val_vector(3, c, VAL_VECTOR, at);
}

/* An argument of kind k (an array for dimensions(), an object for
 * inside() ...). The result is held by the parse: release it with
 * parse_drop. */
static struct value arg_item(struct parser *p, enum val_kind k, const char *fn)
{
	struct srcpos at = parse_peek(p)->pos;
	struct value v = arg(p);
	if (v.kind != k) {
		const char *kind = val_kind_name(v.kind);
		parse_drop(p, &v);
		parse_error_at(p, at, "%s needs %s, not a %s", fn, k == VAL_ARRAY ? "an array" : "an object", kind);
	}
	return v;
}

bool parse_defined(struct parser *p)
{
	const struct token *id = parse_peek(p);
	if (id->kind == TOK_KEYWORD) {
		parse_advance(p);
		return false; /* a reserved word is never declared */
	}
	if (id->kind != TOK_IDENT)
		parse_expected(p, "an identifier");
	const char *name = id->str;
	struct srcpos at = id->pos;
	const struct value *v = parse_lookup(p, name);
	parse_advance(p);
	if (!v || v->kind != VAL_ARRAY || !parse_is(p, TOK_LBRACKET))
		return v != NULL;
	/* A[i]...: is that element set? */
	size_t idx = parse_array_index(p, v->arr, name, at);
	v = parse_lookup(p, name);
	return v && v->kind == VAL_ARRAY && idx < v->arr->count && v->arr->elems[idx].kind != VAL_NONE;
}

/* ---- float functions of one or two floats ---- */

static double f_degrees(double a) { return a * 180.0 / M_PI; }
static double f_radians(double a) { return a * M_PI / 180.0; }
static double f_int(double a) { return trunc(a) + 0.0; /* never -0 */ }
static double f_mod(double a, double b) { return fmod(a, b); }
static double f_div(double a, double b) { return trunc(a / b); }

static const struct math_fn math_fns[] = {
	{KW_ABS, 1, fabs, NULL}, {KW_ACOS, 1, acos, NULL}, {KW_ACOSH, 1, acosh, NULL},
	{KW_ASIN, 1, asin, NULL}, {KW_ASINH, 1, asinh, NULL}, {KW_ATAN, 1, atan, NULL},
	{KW_ATANH, 1, atanh, NULL}, {KW_CEIL, 1, ceil, NULL}, {KW_COS, 1, cos, NULL},
	{KW_COSH, 1, cosh, NULL}, {KW_DEGREES, 1, f_degrees, NULL}, {KW_EXP, 1, exp, NULL},
	{KW_FLOOR, 1, floor, NULL}, {KW_INT, 1, f_int, NULL}, {KW_LN, 1, log, NULL},
	{KW_LOG, 1, log10, NULL}, {KW_RADIANS, 1, f_radians, NULL}, {KW_SIN, 1, sin, NULL},
	{KW_SINH, 1, sinh, NULL}, {KW_SQRT, 1, sqrt, NULL}, {KW_TAN, 1, tan, NULL},
	{KW_TANH, 1, tanh, NULL},
	{KW_ATAN2, 2, NULL, atan2}, {KW_MOD, 2, NULL, f_mod}, {KW_POW, 2, NULL, pow},
	{KW_DIV, 2, NULL, f_div},
};

const struct math_fn *builtin_math_fn(enum kw k)
{
	for (size_t i = 0; i < sizeof math_fns / sizeof math_fns[0]; i++)
		if (math_fns[i].kw == k)
			return &math_fns[i];
	return NULL;
}

/* ---- string formatting ---- */

int parse_format_arg(double x)
{
	/* Far past the widths and precisions parse_format_float honours. */
	return x > 1000 ? 1000 : x < -1000 ? -1000 : x == x ? (int)x : 0;
}

const char *parse_format_float(struct parser *p, double x, int l, int prec)
{
	char buf[512];
	int width = l < 0 ? -l : l;
	if (width > 200)
		width = 200;
	if (prec > 100)
		prec = 100;
	if (prec < 0)
		snprintf(buf, sizeof buf, l < 0 ? "%0*f" : "%*f", width, x);
	else
		snprintf(buf, sizeof buf, l < 0 ? "%0*.*f" : "%*.*f", width, prec, x);
	return parse_intern(p, buf, strlen(buf));
}

/* ---- random numbers (POV-Ray's generator, exactly) ---- */

static double f_seed(struct parser *p, double s)
{
	if (p->nrng == p->caprng) {
		p->caprng = p->caprng ? p->caprng * 2 : 8;
		p->rng = realloc(p->rng, (size_t)p->caprng * sizeof *p->rng);
		if (!p->rng) abort();
	}
	/* POV-Ray takes the seed as a 32-bit int; outside that range (and for
	 * NaN) it gets INT_MIN, as x86's conversion gives (measured:
	 * seed(3e9), seed(1e30) and seed(-1e30) draw what seed(-2^31) does). */
	p->rng[p->nrng] = s >= -2147483648.0 && s < 2147483648.0 ? (uint32_t)(int32_t)s : 0x80000000u;
	return p->nrng++;
}

static double f_rand(struct parser *p, double stream, struct srcpos at)
{
	if (!parse_rng_stream(p, stream))
		parse_error_at(p, at, "rand() needs a stream made by seed(), not %g", stream);
	long i = (long)stream;
	p->rng[i] = p->rng[i] * 1812433253u + 12345u;
	return p->rng[i] / 4294967295.0;
}

/* ---- geometry queries ---- */

/* The integer a bitwise function works on: POV-Ray's 32-bit int, with any
 * value outside its range (and NaN) becoming the smallest int (measured:
 * bitwise_or(3e9, 1) is -2147483647, bitwise_and(2.9e39, 7) is 0). */
static int32_t bit_int(double x)
{
	if (!(x >= -2147483648.0 && x < 2147483648.0))
		return INT32_MIN;
	return (int32_t)x;
}

static struct value f_trace(struct parser *p, struct srcpos at)
{
	struct value o = arg_item(p, VAL_OBJECT, "trace");
	comma(p);
	vec3 from = arg_vec3(p, "trace");
	comma(p);
	vec3 dir = arg_vec3(p, "trace");
	const char *normal_var = NULL;
	if (parse_accept(p, TOK_COMMA)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_IDENT)
			parse_expected(p, "an identifier to receive the normal");
		normal_var = t->str;
		parse_advance(p);
	}
	rparen(p);
	struct ray r = {from, dir};
	struct hit h;
	vec3 pt = v3(0, 0, 0), n = v3(0, 0, 0);
	/* POV-Ray's trace() skips an object whose box the ray misses; that
	 * box can cut off surface (an intersection with a part that holds an
	 * inverse object: see csg.c), so the test is needed, not only fast. */
	if (v3_len(dir) > 0 && object_ray_meets_box(object_world_bounds(o.obj), &r, 0, INFINITY) &&
	    object_intersect(o.obj, &r, 0, INFINITY, &h)) {
		pt = v3_madd(from, dir, h.t);
		/* The leaf's outward normal, turned over once for each inverse
		 * object above it, never toward the ray: POV-Ray's trace(). */
		n = object_normal(h.obj ? h.obj : o.obj, pt, &h);
		if (h.inverted)
			n = v3_neg(n);
	}
	parse_drop(p, &o);
	if (normal_var)
		parse_assign(p, normal_var, false, vec3_value(n, at));
	return vec3_value(pt, at);
}

/* ---- the table ---- */

bool builtin_is_function(enum kw k)
{
	if (builtin_math_fn(k))
		return true;
	switch (k) {
	case KW_MIN: case KW_MAX: case KW_BITWISE_AND: case KW_BITWISE_OR: case KW_BITWISE_XOR:
	case KW_SELECT: case KW_SEED: case KW_RAND: case KW_STRCMP: case KW_STRLEN: case KW_VAL:
	case KW_ASC: case KW_VDOT: case KW_VLENGTH: case KW_DEFINED: case KW_DIMENSIONS:
	case KW_DIMENSION_SIZE: case KW_FILE_EXISTS: case KW_INSIDE: case KW_VCROSS: case KW_VNORMALIZE:
	case KW_VROTATE: case KW_VAXIS_ROTATE: case KW_MIN_EXTENT: case KW_MAX_EXTENT: case KW_TRACE:
	case KW_CHR: case KW_CONCAT: case KW_STR: case KW_STRLWR: case KW_STRUPR: case KW_SUBSTR:
	case KW_VSTR: case KW_DATETIME: case KW_NOW: case KW_VTURBULENCE:
		return true;
	default:
		return false;
	}
}

struct value builtin_call(struct parser *p)
{
	const struct token *t = parse_peek(p);
	enum kw k = (enum kw)t->kw;
	struct srcpos at = t->pos;
	const char *name = kw_names[k];
	parse_advance(p);
	if (k == KW_NOW) {
		/* Days since 2000-01-01 00:00:00 UTC. */
		return val_float(((double)time(NULL) - 946684800.0) / 86400.0, at);
	}
	lparen(p);
	struct value r;
	const struct math_fn *m = builtin_math_fn(k);
	if (m) {
		double a = arg_float(p, name), b = 0;
		if (m->nargs == 2) {
			comma(p);
			b = arg_float(p, name);
		}
		rparen(p);
		double x = m->nargs == 1 ? m->f1(a) : m->f2(a, b);
		if (!isfinite(x))
			parse_error_at(p, at, "%s(): the result is not a finite number (is the argument out of range?)", name);
		return val_float(x, at);
	}
	switch (k) {
	case KW_MIN: case KW_MAX: case KW_BITWISE_AND: case KW_BITWISE_OR: case KW_BITWISE_XOR: {
		double acc = arg_float(p, name);
		int n = 1;
		while (parse_accept(p, TOK_COMMA)) {
			double x = arg_float(p, name);
			n++;
			switch (k) {
			case KW_MIN: acc = x < acc ? x : acc; break;
			case KW_MAX: acc = x > acc ? x : acc; break;
			case KW_BITWISE_AND: acc = (double)(bit_int(acc) & bit_int(x)); break;
			case KW_BITWISE_OR: acc = (double)(bit_int(acc) | bit_int(x)); break;
			default: acc = (double)(bit_int(acc) ^ bit_int(x)); break;
			}
		}
		rparen(p);
		if (n < 2 && (k == KW_MIN || k == KW_MAX))
			parse_error_at(p, at, "%s() needs at least two arguments", name);
		return val_float(acc, at);
	}
	case KW_SELECT: {
		double c = arg_float(p, name);
		comma(p);
		struct value a = arg(p);
		comma(p);
		struct value b = arg(p);
		bool four = parse_accept(p, TOK_COMMA);
		struct value d = {0};
		if (four)
			d = arg(p);
		rparen(p);
		if (c < 0)
			r = a;
		else if (!four || c == 0)
			r = b;
		else
			r = d;
		return r;
	}
	case KW_SEED: r = val_float(f_seed(p, arg_float(p, name)), at); break;
	case KW_RAND: r = val_float(f_rand(p, arg_float(p, name), at), at); break;
	case KW_STRCMP: {
		const char *a = arg_string(p, name);
		comma(p);
		const char *b = arg_string(p, name);
		/* POV-Ray's: the difference of the first codes that differ
		 * (the end counting as 0), measured: strcmp("abc", "ab") = 99. */
		double c = 0;
		for (;;) {
			size_t la = 0, lb = 0;
			uint32_t ca = *a ? ustr_get(a, &la) : 0, cb = *b ? ustr_get(b, &lb) : 0;
			if (ca != cb || !ca) {
				c = (double)ca - (double)cb;
				break;
			}
			a += la;
			b += lb;
		}
		r = val_float(c, at);
		break;
	}
	case KW_STRLEN: r = val_float((double)ustr_len(arg_string(p, name)), at); break;
	case KW_VAL: r = val_float(strtod(arg_string(p, name), NULL), at); break;
	case KW_ASC: {
		const char *s = arg_string(p, name);
		size_t l;
		r = val_float(*s ? ustr_get(s, &l) : 0, at);
		break;
	}
	case KW_VDOT: {
		vec3 a = arg_vec3(p, name);
		comma(p);
		r = val_float(v3_dot(a, arg_vec3(p, name)), at);
		break;
	}
	case KW_VTURBULENCE: {
		/* vturbulence(Lambda, Omega, Octaves, A): the turbulence vector
		 * of the default noise generator, as warp { turbulence } uses. */
		struct turbulence tb;
		tb.lambda = arg_float(p, name);
		comma(p);
		tb.omega = arg_float(p, name);
		comma(p);
		/* POV-Ray computes from 1 to 10 octaves whatever the argument
		 * (measured: 0 and -5 give 1 octave's value, 11, 100 and 2e9
		 * the 10th's); 2e9 octaves ran for minutes here. */
		int oct = parse_int_of(arg_float(p, name));
		tb.octaves = oct < 1 ? 1 : oct > 10 ? 10 : oct;
		comma(p);
		vec3 a = arg_vec3(p, name);
		tb.amount = v3(1, 1, 1);
		r = vec3_value(turbulence3(a, &tb, 2), at);
		break;
	}
	case KW_VLENGTH: {
		struct value v = arg(p);
		parse_need_numeric(p, &v, name);
		double s = 0;
		for (int i = 0; i < v.n; i++)
			s += v.v[i] * v.v[i];
		r = val_float(sqrt(s), at);
		break;
	}
	case KW_DEFINED: r = val_float(parse_defined(p), at); break;
	case KW_DIMENSIONS: {
		struct value a = arg_item(p, VAL_ARRAY, name);
		r = val_float(a.arr->ndims, at);
		parse_drop(p, &a);
		break;
	}
	case KW_DIMENSION_SIZE: {
		struct value a = arg_item(p, VAL_ARRAY, name);
		comma(p);
		double d = arg_float(p, name);
		int i = parse_int_of(d);
		r = val_float(i >= 1 && i <= a.arr->ndims ? a.arr->dims[i - 1] : 0, at);
		parse_drop(p, &a);
		break;
	}
	case KW_FILE_EXISTS: {
		const char *f = arg_string(p, name);
		bool ok = access(f, R_OK) == 0;
		char buf[4096];
		for (size_t i = 0; !ok && i < p->o->nlib_paths; i++) {
			snprintf(buf, sizeof buf, "%s/%s", p->o->lib_paths[i], f);
			ok = access(buf, R_OK) == 0;
		}
		r = val_float(ok, at);
		break;
	}
	case KW_INSIDE: {
		struct value o = arg_item(p, VAL_OBJECT, name);
		comma(p);
		r = val_float(object_inside(o.obj, arg_vec3(p, name)), at);
		parse_drop(p, &o);
		break;
	}
	case KW_VCROSS: {
		vec3 a = arg_vec3(p, name);
		comma(p);
		r = vec3_value(v3_cross(a, arg_vec3(p, name)), at);
		break;
	}
	case KW_VNORMALIZE: {
		vec3 a = arg_vec3(p, name);
		if (v3_len(a) == 0)
			parse_error_at(p, at, "vnormalize() of a zero-length vector");
		r = vec3_value(v3_norm(a), at);
		break;
	}
	case KW_VROTATE: {
		vec3 a = arg_vec3(p, name);
		comma(p);
		struct xform x = xform_rotate_plain(arg_vec3(p, name));
		r = vec3_value(mat_point(&x.fwd, a), at);
		break;
	}
	case KW_VAXIS_ROTATE: {
		vec3 a = arg_vec3(p, name);
		comma(p);
		vec3 axis = arg_vec3(p, name);
		if (v3_len(axis) == 0)
			parse_error_at(p, at, "vaxis_rotate() about a zero-length axis");
		/* Scaled by the reciprocal of its length, as POV-Ray does: the
		 * last bits of the result depend on it. */
		axis = v3_scale(axis, 1.0 / v3_len(axis));
		comma(p);
		mat4 rot = mat_axis_rotation(axis, arg_float(p, name));
		r = vec3_value(mat_point(&rot, a), at);
		break;
	}
	case KW_MIN_EXTENT: case KW_MAX_EXTENT: {
		struct value o = arg_item(p, VAL_OBJECT, name);
		struct aabb b = object_world_bounds(o.obj);
		parse_drop(p, &o);
		/* As POV-Ray stores it, in single precision; an unbounded
		 * object's box is +-1e10. */
		b = object_box_single(b);
		r = vec3_value(k == KW_MIN_EXTENT ? b.lo : b.hi, at);
		break;
	}
	case KW_TRACE: return f_trace(p, at);
	case KW_CHR: {
		double c = trunc(arg_float(p, name));
		/* POV-Ray's codes are 16 bits: "Value 70000 cannot be used in chr()". */
		if (!(c >= 0 && c <= USTR_MAX))
			parse_error_at(p, at, "chr(%.15g): a character code is 0 to %d", c, USTR_MAX);
		char ch[4] = {0};
		size_t n = c == 0 ? 1 : ustr_put(ch, (uint32_t)c);
		r = str_value(p, ch, n, at);
		break;
	}
	case KW_CONCAT: {
		size_t cap = 256, len = 0;
		char *buf = malloc(cap);
		if (!buf) abort();
		/* Owned by the parse while the arguments are read: one may fail. */
		int slot = parse_own(p, buf, free);
		do {
			const char *s = arg_string(p, name);
			size_t n = strlen(s);
			if (len + n > p->lim.string_length)
				parse_error_at(p, at, "concat() would make a string longer than %zu bytes (lucent --limit "
				               "string-length=N raises the limit)", p->lim.string_length);
			if (len + n + 1 > cap) {
				while (len + n + 1 > cap)
					cap *= 2;
				buf = realloc(buf, cap);
				if (!buf) abort();
				p->owned[slot].ptr = buf;
			}
			memcpy(buf + len, s, n);
			len += n;
		} while (parse_accept(p, TOK_COMMA));
		r = str_value(p, buf, len, at);
		parse_release(p, slot);
		free(buf);
		break;
	}
	case KW_STR: {
		double x = arg_float(p, name);
		comma(p);
		double l = arg_float(p, name);
		comma(p);
		double pr = arg_float(p, name);
		r = (struct value){.kind = VAL_STRING, .pos = at, .str = parse_format_float(p, x, parse_format_arg(l), parse_format_arg(pr))};
		break;
	}
	case KW_STRLWR: case KW_STRUPR: {
		const char *s = arg_string(p, name);
		size_t n = strlen(s);
		char *buf = malloc(n + 1);
		if (!buf) abort();
		for (size_t i = 0; i < n; i++)
			buf[i] = (char)(k == KW_STRLWR ? tolower((unsigned char)s[i]) : toupper((unsigned char)s[i]));
		r = str_value(p, buf, n, at);
		free(buf);
		break;
	}
	case KW_SUBSTR: {
		const char *s = arg_string(p, name);
		comma(p);
		double start = arg_float(p, name);
		comma(p);
		double len = arg_float(p, name);
		size_t n = ustr_len(s);
		/* Checked as floats first: a huge one has no long value. */
		double fst = trunc(start), fln = trunc(len);
		if (!(fst >= 1) || !(fln >= 0) || fst + fln - 1 > (double)n)
			parse_error_at(p, at, "substr(\"%s\", %.15g, %.15g) reaches past the end of the string (length %zu)", s,
			               fst == fst ? fst : 0, fln == fln ? fln : 0, n);
		size_t st = ustr_offset(s, (size_t)fst - 1);
		r = str_value(p, s + st, ustr_offset(s + st, (size_t)fln), at);
		break;
	}
	case KW_VSTR: {
		double nd = arg_float(p, name);
		comma(p);
		struct value v = arg(p);
		parse_need_numeric(p, &v, name);
		comma(p);
		const char *sep = arg_string(p, name);
		comma(p);
		double l = arg_float(p, name);
		comma(p);
		double pr = arg_float(p, name);
		int n = parse_format_arg(nd);
		if (n < 2) n = 2;
		if (n > 5) n = 5;
		/* More components than N: the first N are written (POV-Ray's
		 * behaviour, whatever its manual says). A float is a vector with only its first component set here
		 * (POV-Ray's behaviour, whatever its manual says). */
		for (int i = v.n; i < n; i++)
			v.v[i] = 0;
		size_t cap = 64, len = 0;
		char *buf = malloc(cap);
		if (!buf) abort();
		for (int i = 0; i < n; i++) {
			const char *part = parse_format_float(p, v.v[i], parse_format_arg(l), parse_format_arg(pr));
			size_t need = strlen(part) + (i ? strlen(sep) : 0);
			while (len + need + 1 > cap) {
				cap *= 2;
				buf = realloc(buf, cap);
				if (!buf) abort();
			}
			if (i) {
				memcpy(buf + len, sep, strlen(sep));
				len += strlen(sep);
			}
			memcpy(buf + len, part, strlen(part));
			len += strlen(part);
		}
		r = str_value(p, buf, len, at);
		free(buf);
		break;
	}
	case KW_DATETIME: {
		double days = arg_float(p, name);
		const char *fmt = "%Y-%m-%d %H:%M:%SZ";
		if (parse_accept(p, TOK_COMMA))
			fmt = arg_string(p, name);
		time_t tt = (time_t)(days * 86400.0 + 946684800.0);
		struct tm tmv;
		gmtime_r(&tt, &tmv);
		char buf[512];
		size_t n = strftime(buf, sizeof buf, fmt, &tmv);
		r = str_value(p, buf, n, at);
		break;
	}
	default:
		parse_error_at(p, at, "'%s' is not a function", name);
	}
	rparen(p);
	return r;
}

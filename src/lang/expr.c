/* expr.c: expressions. Numbers, vectors and colours are one family of
 * values with 1 to 5 components; operators promote a float to every
 * component and a shorter vector by padding with zeros, as POV-Ray does.
 * Binary operators are parsed by one precedence-climbing function driven
 * by a table of binding strengths. */
#include "lang/parser.h"

#include "lang/intern.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- helpers ---- */

void parse_need_numeric(struct parser *p, const struct value *v, const char *what)
{
	if (!val_is_numeric(v))
		parse_error_at(p, v->pos, "%s needs a number, vector or color, not a %s", what, val_kind_name(v->kind));
}

void parse_need_float(struct parser *p, const struct value *v, const char *what)
{
	if (v->kind != VAL_FLOAT)
		parse_error_at(p, v->pos, "%s needs a float, not a %s", what, val_kind_name(v->kind));
}

#define need_numeric parse_need_numeric
#define need_float parse_need_float

static struct value parse_unary(struct parser *p);
static struct value parse_binary(struct parser *p, int min_prec, bool in_vector);
static struct value parse_cond(struct parser *p, bool in_vector);

/* ---- binary operators ---- */

enum op { OP_NONE, OP_OR, OP_AND, OP_LT, OP_LE, OP_EQ, OP_GE, OP_GT, OP_NE, OP_ADD, OP_SUB, OP_MUL, OP_DIV };

static const struct {
	int prec;       /* binding strength: higher binds tighter */
} ops[] = {
	/* & and | share one level, left to right, as in POV-Ray. */
	[OP_NONE] = {0}, [OP_OR] = {2}, [OP_AND] = {2},
	[OP_LT] = {3}, [OP_LE] = {3}, [OP_EQ] = {3}, [OP_GE] = {3}, [OP_GT] = {3}, [OP_NE] = {3},
	[OP_ADD] = {4}, [OP_SUB] = {4}, [OP_MUL] = {5}, [OP_DIV] = {5},
};

static enum op binop(enum tok_kind k, bool in_vector, bool rel_ok)
{
	if (!rel_ok && k != TOK_PLUS && k != TOK_MINUS && k != TOK_STAR && k != TOK_SLASH)
		return OP_NONE;
	switch (k) {
	case TOK_BAR: return OP_OR;
	case TOK_AMP: return OP_AND;
	case TOK_LT: return OP_LT;
	case TOK_LE: return OP_LE;
	case TOK_EQ: return OP_EQ;
	case TOK_GE: return OP_GE;
	/* Inside < >, a bare '>' closes the vector; compare in parentheses. */
	case TOK_GT: return in_vector ? OP_NONE : OP_GT;
	case TOK_NE: return OP_NE;
	case TOK_PLUS: return OP_ADD;
	case TOK_MINUS: return OP_SUB;
	case TOK_STAR: return OP_MUL;
	case TOK_SLASH: return OP_DIV;
	default: return OP_NONE;
	}
}

/* POV-Ray's tolerance for equality and truth: values within 1e-10 of
 * each other are equal, and within 1e-10 of zero are false. */
#define EQ_EPSILON 1e-10
bool parse_truthy(double x) { return fabs(x) > EQ_EPSILON; }

double parse_compare(enum parse_cmp op, double x, double y)
{
	switch (op) {
	case CMP_OR: return parse_truthy(x) || parse_truthy(y);
	case CMP_AND: return parse_truthy(x) && parse_truthy(y);
	/* < and > are exact; the others allow the tolerance. */
	case CMP_LT: return x < y;
	case CMP_LE: return x <= y + EQ_EPSILON;
	case CMP_EQ: return fabs(x - y) <= EQ_EPSILON;
	case CMP_GE: return x >= y - EQ_EPSILON;
	case CMP_GT: return x > y;
	case CMP_NE: return fabs(x - y) > EQ_EPSILON;
	}
	return 0;
}

/* The operators OP_OR .. OP_NE in parse_cmp's order. */
static double compare(enum op op, double x, double y)
{
	return parse_compare((enum parse_cmp)(op - OP_OR), x, y);
}

static const char *op_name(enum op op)
{
	static const char *const names[] = {"?", "'|'", "'&'", "'<'", "'<='", "'='", "'>='", "'>'", "'!='", "'+'", "'-'", "'*'", "'/'"};
	return names[op];
}

static struct value apply(struct parser *p, enum op op, struct value a, struct value b, struct srcpos at)
{
	if (op >= OP_LT && op <= OP_NE && a.kind == VAL_STRING && b.kind == VAL_STRING) {
		int c = strcmp(a.str, b.str);
		return val_float(compare(op, c, 0), a.pos);
	}
	if (!val_is_numeric(&a) || !val_is_numeric(&b)) {
		const struct value *bad = val_is_numeric(&a) ? &b : &a;
		parse_error_at(p, at, "%s needs numbers, vectors or colors%s, not a %s", op_name(op),
		               op >= OP_LT && op <= OP_NE ? " (or two strings)" : "", val_kind_name(bad->kind));
	}
	int n = a.n > b.n ? a.n : b.n;
	val_widen(&a, n);
	val_widen(&b, n);
	struct value r = a;
	r.kind = (a.kind == VAL_COLOR || b.kind == VAL_COLOR) ? VAL_COLOR : n > 1 ? VAL_VECTOR : VAL_FLOAT;
	if (op <= OP_NE) {
		/* Comparisons and logic work component by component. */
		for (int i = 0; i < n; i++)
			r.v[i] = compare(op, a.v[i], b.v[i]);
		return r;
	}
	for (int i = 0; i < n; i++) {
		switch (op) {
		case OP_ADD: r.v[i] = a.v[i] + b.v[i]; break;
		case OP_SUB: r.v[i] = a.v[i] - b.v[i]; break;
		case OP_MUL: r.v[i] = a.v[i] * b.v[i]; break;
		case OP_DIV:
			if (b.v[i] == 0)
				parse_error_at(p, at, "division by zero");
			r.v[i] = a.v[i] / b.v[i];
			break;
		default: break;
		}
	}
	if (r.kind == VAL_COLOR)
		r.n = 5;
	return r;
}

/* binary := unary { op binary-of-higher-strength } */
static struct value parse_binary(struct parser *p, int min_prec, bool in_vector)
{
	struct value a = parse_unary(p);
	for (;;) {
		const struct token *t = parse_peek_cont(p);
		enum op op = binop((enum tok_kind)t->kind, in_vector, p->rel_ok);
		if (op == OP_NONE || ops[op].prec < min_prec)
			return a;
		struct srcpos at = t->pos;
		parse_advance(p);
		struct value b = parse_binary(p, ops[op].prec + 1, in_vector);
		a = apply(p, op, a, b, at);
	}
}

/* cond := binary [ '?' cond ':' cond ] */
static struct value parse_cond(struct parser *p, bool in_vector)
{
	if (++p->expr_depth > (int)p->lim.expr_depth)
		parse_error(p, "expression nested too deeply (more than %d levels; lucent --limit expr-depth=N raises it)", (int)p->lim.expr_depth);
	struct value c = parse_binary(p, 1, in_vector);
	if (p->rel_ok && parse_peek_cont(p)->kind == TOK_QUESTION) {
		need_float(p, &c, "the condition of '?:'");
		c.v[0] = parse_truthy(c.v[0]);
		parse_advance(p);
		struct value a = parse_cond(p, in_vector);
		parse_expect(p, TOK_COLON);
		struct value b = parse_cond(p, in_vector);
		if (c.v[0] != 0) {
			parse_drop(p, &b);
			c = a;
		} else {
			parse_drop(p, &a);
			c = b;
		}
	}
	p->expr_depth--;
	return c;
}

/* ---- primaries ---- */

/* '<' expr { [','] expr } '>'  (2 to 5 components). As in POV-Ray the
 * commas may be left out: <1 2 3> is <1, 2, 3>, while <1 -2 3> is <-1, 3>
 * (the '-' continues the first component). */
static struct value parse_vector_literal(struct parser *p)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	double c[5];
	int n = 0;
	for (;;) {
		struct value e = parse_cond(p, true);
		need_float(p, &e, "a vector component");
		if (n == 5)
			parse_error_at(p, e.pos, "a vector has at most 5 components");
		c[n++] = e.v[0];
		if (parse_accept(p, TOK_COMMA))
			continue;
		if (parse_is(p, TOK_GT))
			break;
		if (n < 5 && parse_starts_expression(p))
			continue;
		parse_expected(p, "',' or '>' in vector");
	}
	parse_advance(p);
	if (n < 2)
		parse_error_at(p, at, "a vector needs at least 2 components");
	return val_vector(n, c, VAL_VECTOR, at);
}

int parse_number_list(struct parser *p, double *out, int max)
{
	parse_expect(p, TOK_LT);
	int n = 0;
	for (;;) {
		struct value e = parse_cond(p, true);
		need_float(p, &e, "a list entry");
		if (n == max)
			parse_error_at(p, e.pos, "too many entries: at most %d", max);
		out[n++] = e.v[0];
		if (parse_accept(p, TOK_COMMA))
			continue;
		if (parse_accept(p, TOK_GT))
			return n;
		parse_expected(p, "',' or '>'");
	}
}

static double srgb_decode(double v)
{
	return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

void parse_keyword_color(enum kw k, const double *v, int n, bool is_float, double c[5])
{
	double w[5];
	for (int i = 0; i < 5; i++)
		w[i] = i < n ? v[i] : is_float ? v[0] : 0;
	c[0] = w[0];
	c[1] = w[1];
	c[2] = w[2];
	c[3] = c[4] = 0;
	if (k == KW_RGBF || k == KW_SRGBF)
		c[3] = w[3];
	else if (k == KW_RGBT || k == KW_SRGBT)
		c[4] = w[3];
	else if (k == KW_RGBFT || k == KW_SRGBFT) {
		c[3] = w[3];
		c[4] = w[4];
	}
	if (k == KW_SRGB || k == KW_SRGBF || k == KW_SRGBT || k == KW_SRGBFT)
		for (int i = 0; i < 3; i++)
			c[i] = srgb_decode(c[i]);
}

static int color_component(enum kw k);

/* Trailing 'red F', 'transmit F' ... that set one component of c. */
static void color_components(struct parser *p, struct value *c)
{
	for (;;) {
		const struct token *t = parse_peek_cont(p);
		if (t->kind != TOK_KEYWORD)
			return;
		int i = color_component((enum kw)t->kw);
		if (i < 0)
			return;
		parse_advance(p);
		struct value e = parse_binary(p, 4, false);
		need_float(p, &e, "a color component");
		c->v[i] = e.v[0];
	}
}

static bool is_srgb_kw(enum kw k)
{
	return k == KW_SRGB || k == KW_SRGBF || k == KW_SRGBT || k == KW_SRGBFT;
}

/* rgb/rgbf/rgbt/rgbft/srgb... VECTOR: a colour from a vector expression.
 * An sRGB colour is decoded to linear light, then brought to the working
 * gamma (measured: with assumed_gamma 2.2, srgb 0.5 is 0.214^(1/2.2));
 * before assumed_gamma is set it is POV-Ray's parse error. */
static struct value parse_color_keyword(struct parser *p, enum kw k)
{
	struct srcpos at = parse_peek(p)->pos;
	if (is_srgb_kw(k) && !p->scene->gs.assumed_gamma_set)
		parse_error_at(p, at, "an sRGB color (%s) cannot be used before global_settings { assumed_gamma } is set",
		               kw_names[k]);
	parse_advance(p);
	struct value e = parse_binary(p, 4, false);
	need_numeric(p, &e, kw_names[k]);
	double c[5];
	parse_keyword_color(k, e.v, e.n, e.kind == VAL_FLOAT, c);
	double g = p->scene->gs.assumed_gamma;
	if (is_srgb_kw(k) && g != 1.0 && g > 0)
		for (int i = 0; i < 3; i++)
			if (c[i] > 0)
				c[i] = pow(c[i], 1.0 / g);
	struct value r = val_vector(5, c, VAL_COLOR, at);
	color_components(p, &r);
	return r;
}

static int color_component(enum kw k)
{
	switch (k) {
	case KW_RED: return 0;
	case KW_GREEN: return 1;
	case KW_BLUE: return 2;
	case KW_FILTER: return 3;
	case KW_TRANSMIT: return 4;
	default: return -1;
	}
}

/* color [colour_body]: 'color' then a colour expression, or the component
 * form 'color red 1 green 0.5 ...' (missing components are 0). */
static struct value parse_color_body(struct parser *p, struct srcpos at)
{
	struct value c;
	/* An identifier is not fetched (which looks it up for a macro call)
	 * before its compiled form is tried: that form only runs where the
	 * name holds a colour or a number. */
	const struct token *t = parse_peek_raw(p);
	if (!t || t->kind == TOK_HASH)
		t = parse_peek(p);
	if (t->kind == TOK_KEYWORD && color_component((enum kw)t->kw) >= 0) {
		double z[5] = {0};
		c = val_vector(5, z, VAL_COLOR, at);
	} else {
		/* `color C` in every object a macro makes: read it compiled. */
		struct exprcache_ticket tk;
		if (!exprcache_try_operand(p, &c, &tk)) {
			c = parse_binary(p, 1, false);
			exprcache_record(p, &tk, &c);
		}
		need_numeric(p, &c, "a color");
		if (c.kind == VAL_FLOAT) {
			/* A bare float sets all five components (the manual's
			 * pitfall: filter and transmit too). */
			double z[5] = {c.v[0], c.v[0], c.v[0], c.v[0], c.v[0]};
			c = val_vector(5, z, VAL_COLOR, at);
		} else if (c.kind != VAL_COLOR) {
			val_widen(&c, 3);
			double z[5] = {c.v[0], c.v[1], c.v[2], c.n > 3 ? c.v[3] : 0, c.n > 4 ? c.v[4] : 0};
			c = val_vector(5, z, VAL_COLOR, at);
		}
	}
	color_components(p, &c);
	return c;
}

/* The components of a named vector constant. */
static bool builtin_vector(enum kw k, struct value *out, struct srcpos pos)
{
	static const double X[3] = {1, 0, 0}, Y[3] = {0, 1, 0}, Z[3] = {0, 0, 1};
	static const double T[4] = {0, 0, 0, 1}, U[2] = {1, 0}, V[2] = {0, 1};
	switch (k) {
	case KW_X: *out = val_vector(3, X, VAL_VECTOR, pos); return true;
	case KW_Y: *out = val_vector(3, Y, VAL_VECTOR, pos); return true;
	case KW_Z: *out = val_vector(3, Z, VAL_VECTOR, pos); return true;
	case KW_T: *out = val_vector(4, T, VAL_VECTOR, pos); return true;
	case KW_U: *out = val_vector(2, U, VAL_VECTOR, pos); return true;
	case KW_V: *out = val_vector(2, V, VAL_VECTOR, pos); return true;
	default: return false;
	}
}

static struct value parse_keyword_primary(struct parser *p)
{
	const struct token *t = parse_peek(p);
	enum kw k = (enum kw)t->kw;
	struct srcpos at = t->pos;
	struct value v;
	if (builtin_vector(k, &v, at)) {
		parse_advance(p);
		return v;
	}
	switch (k) {
	case KW_PI: parse_advance(p); return val_float(M_PI, at);
	case KW_TRUE: case KW_YES: case KW_ON: parse_advance(p); return val_float(1, at);
	case KW_FALSE: case KW_NO: case KW_OFF: parse_advance(p); return val_float(0, at);
	case KW_CLOCK: parse_advance(p); return val_float(p->o->clock, at);
	case KW_CLOCK_DELTA: parse_advance(p); return val_float(0, at);
	case KW_CLOCK_ON: parse_advance(p); return val_float(0, at);
	case KW_FRAME_NUMBER: case KW_INITIAL_FRAME: case KW_FINAL_FRAME:
		parse_advance(p);
		return val_float(0, at); /* no animation */
	case KW_INITIAL_CLOCK: parse_advance(p); return val_float(0, at);
	case KW_FINAL_CLOCK: parse_advance(p); return val_float(0, at);
	case KW_IMAGE_WIDTH: parse_advance(p); return val_float(p->o->image_width, at);
	case KW_IMAGE_HEIGHT: parse_advance(p); return val_float(p->o->image_height, at);
	case KW_VERSION: parse_advance(p); return val_float(p->version, at);
	case KW_INPUT_FILE_NAME: {
		parse_advance(p);
		struct value sv = {.kind = VAL_STRING, .pos = at, .str = parse_intern(p, p->o->input, strlen(p->o->input))};
		return sv;
	}
	case KW_RGB: case KW_RGBF: case KW_RGBT: case KW_RGBFT:
	case KW_SRGB: case KW_SRGBF: case KW_SRGBT: case KW_SRGBFT:
		return parse_color_keyword(p, k);
	case KW_COLOR: case KW_COLOUR:
		parse_advance(p);
		return parse_color_body(p, at);
	default:
		if (builtin_is_function(k)) {
			/* Inside a call's parentheses everything binds. */
			bool rel = parse_set_rel(p, true);
			struct value r = builtin_call(p);
			p->rel_ok = rel;
			return r;
		}
	}
	parse_expected(p, "an expression");
}

static void free_value_holder(void *h)
{
	val_clear(h);
	free(h);
}

/* A copy of an identifier's value for an expression. Scene items (objects,
 * textures, ...) are held by the parse until a consumer takes them, so an
 * error in the rest of the expression frees them. */
static struct value ident_value_copy(struct parser *p, const struct value *v, struct srcpos at)
{
	struct value c = val_copy(v);
	c.pos = at;
	switch (c.kind) {
	case VAL_OBJECT: case VAL_TEXTURE: case VAL_PIGMENT: case VAL_FINISH: case VAL_CAMERA:
	case VAL_NORMAL: case VAL_INTERIOR: case VAL_MATERIAL: case VAL_MAP:
	case VAL_LIGHT: case VAL_TRANSFORM: case VAL_ARRAY: case VAL_SPLINE: case VAL_FUNCTION:
	case VAL_FILE: case VAL_MACRO: case VAL_FOG: case VAL_SKY_SPHERE: case VAL_RAINBOW: {
		struct value *h = malloc(sizeof *h);
		if (!h) abort();
		*h = c;
		c.owner = parse_own(p, h, free_value_holder) + 1;
		break;
	}
	default:
		break;
	}
	return c;
}

/* '[' INT ']' ... : the element of an array an index list selects. */
static const struct value *array_element(struct parser *p, const struct array *a, const char *name, struct srcpos at)
{
	size_t idx = parse_array_index(p, a, name, at);
	const struct value *el = &a->elems[idx];
	if (el->kind == VAL_NONE)
		parse_error_at(p, at, "element of array '%s' used before it was given a value", name);
	return el;
}

static struct value parse_primary(struct parser *p)
{
	const struct token *t = parse_peek(p);
	struct srcpos at = t->pos;
	switch (t->kind) {
	case TOK_NUMBER: {
		double x = t->num;
		parse_advance(p);
		return val_float(x, at);
	}
	case TOK_LPAREN: {
		parse_advance(p);
		bool rel = parse_set_rel(p, true);
		struct value v = parse_cond(p, false);
		p->rel_ok = rel;
		parse_expect(p, TOK_RPAREN);
		v.pos = at;
		return v;
	}
	case TOK_LT:
		return parse_vector_literal(p);
	case TOK_STRING: {
		struct value v = {.kind = VAL_STRING, .pos = at, .str = parse_charset_literal(p, t->str, at)};
		parse_advance(p);
		return v;
	}
	case TOK_IDENT: {
		const char *name = t->str;
		struct value *v = parse_lookup(p, name);
		if (!v)
			parse_undefined(p, name);
		parse_note_use(p, v, name, at);
		/* Hold the binding while its suffix is read: a macro frame that
		 * ends meanwhile must not take the value with it. */
		struct value c = ident_value_copy(p, v, at);
		parse_advance(p);
		/* A[i][j]: an element, and an element of an element array. */
		while (c.kind == VAL_ARRAY && parse_peek_cont(p)->kind == TOK_LBRACKET) {
			struct value el = ident_value_copy(p, array_element(p, c.arr, name, at), at);
			parse_drop(p, &c);
			c = el;
		}
		if ((c.kind == VAL_FUNCTION || c.kind == VAL_SPLINE) && parse_peek_cont(p)->kind == TOK_LPAREN) {
			struct value r;
			if (c.kind == VAL_FUNCTION) {
			{
				bool rel = parse_set_rel(p, true);
				r = parse_call_function(p, c.fn, at);
				p->rel_ok = rel;
			}
			} else {
				parse_advance(p);
				struct value tv = parse_expression(p);
				need_float(p, &tv, "a spline's parameter");
				int kind = -1;
				if (parse_accept(p, TOK_COMMA)) {
					static const enum kw kinds[] = {KW_LINEAR_SPLINE, KW_QUADRATIC_SPLINE, KW_CUBIC_SPLINE, KW_NATURAL_SPLINE};
					for (int i = 0; i < 4 && kind < 0; i++)
						if (parse_accept_kw(p, kinds[i]))
							kind = i;
					if (kind < 0)
						parse_expected(p, "a spline type");
				}
				parse_expect(p, TOK_RPAREN);
				r = spline_eval_as(c.spl, tv.v[0], kind, at);
			}
			parse_drop(p, &c);
			return r;
		}
		return c;
	}
	case TOK_KEYWORD:
		return parse_keyword_primary(p);
	default:
		parse_expected(p, "an expression");
	}
}

/* postfix := primary { '.' item } */
static struct value parse_postfix(struct parser *p)
{
	struct value v = parse_primary(p);
	while (parse_peek_cont(p)->kind == TOK_DOT) {
		parse_advance(p);
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_KEYWORD)
			parse_expected(p, "a component name after '.'");
		need_numeric(p, &v, "'.'");
		int i;
		switch (t->kw) {
		case KW_X: case KW_U: case KW_RED: i = 0; break;
		case KW_Y: case KW_V: case KW_GREEN: i = 1; break;
		case KW_Z: case KW_BLUE: i = 2; break;
		case KW_T: case KW_FILTER: i = 3; break;
		case KW_TRANSMIT: i = 4; break;
		case KW_GRAY: i = -1; break;
		default: parse_expected(p, "a component name after '.'");
		}
		if (i < 0) {
			val_widen(&v, 3);
			v = val_float(0.297 * v.v[0] + 0.589 * v.v[1] + 0.114 * v.v[2], v.pos);
		} else {
			if (v.kind == VAL_FLOAT)
				val_widen(&v, 5);
			if (i >= v.n)
				parse_error(p, "this %d-component value has no '.%s'", v.n, kw_names[t->kw]);
			v = val_float(v.v[i], v.pos);
		}
		parse_advance(p);
	}
	return v;
}

/* unary := ('-' | '+' | '!') unary | postfix */
static struct value parse_unary(struct parser *p)
{
	const struct token *t = parse_peek(p);
	struct srcpos at = t->pos;
	if (t->kind == TOK_MINUS || t->kind == TOK_PLUS || t->kind == TOK_BANG) {
		enum tok_kind k = (enum tok_kind)t->kind;
		parse_advance(p);
		if (++p->expr_depth > (int)p->lim.expr_depth)
			parse_error(p, "expression nested too deeply (more than %d levels; lucent --limit expr-depth=N raises it)", (int)p->lim.expr_depth);
		struct value v = parse_unary(p);
		p->expr_depth--;
		need_numeric(p, &v, k == TOK_BANG ? "'!'" : "a sign");
		if (k == TOK_MINUS)
			for (int i = 0; i < v.n; i++)
				v.v[i] = -v.v[i];
		if (k == TOK_BANG)
			for (int i = 0; i < v.n; i++)
				v.v[i] = !parse_truthy(v.v[i]);
		v.pos = at;
		return v;
	}
	return parse_postfix(p);
}

/* ---- entry points ---- */

struct value parse_expression(struct parser *p)
{
	struct value v;
	struct exprcache_ticket tk;
	if (exprcache_try(p, &v, &tk))
		return v;
	v = parse_cond(p, false);
	exprcache_record(p, &tk, &v);
	return v;
}

bool parse_starts_expression(struct parser *p)
{
	const struct token *t = parse_peek(p);
	switch (t->kind) {
	case TOK_NUMBER: case TOK_LPAREN: case TOK_LT: case TOK_STRING: case TOK_IDENT:
	case TOK_MINUS: case TOK_PLUS: case TOK_BANG:
		return true;
	case TOK_KEYWORD: {
		struct value v;
		if (builtin_vector((enum kw)t->kw, &v, t->pos))
			return true;
		switch (t->kw) {
		case KW_PI: case KW_TRUE: case KW_YES: case KW_ON: case KW_FALSE: case KW_NO: case KW_OFF:
		case KW_CLOCK: case KW_CLOCK_DELTA: case KW_CLOCK_ON: case KW_IMAGE_WIDTH: case KW_IMAGE_HEIGHT:
		case KW_VERSION: case KW_RGB: case KW_RGBF: case KW_RGBT: case KW_RGBFT: case KW_SRGB:
		case KW_SRGBF: case KW_SRGBT: case KW_SRGBFT: case KW_COLOR: case KW_COLOUR:
		case KW_FRAME_NUMBER: case KW_INITIAL_FRAME: case KW_FINAL_FRAME: case KW_INITIAL_CLOCK:
		case KW_FINAL_CLOCK: case KW_INPUT_FILE_NAME:
			return true;
		default:
			return builtin_is_function((enum kw)t->kw);
		}
	}
	default:
		return false;
	}
}

double parse_float(struct parser *p)
{
	/* A float expression's compiled form gives the number directly. */
	double x;
	struct exprcache_ticket tk;
	if (exprcache_try_float(p, &x, &tk))
		return x;
	struct value v = parse_cond(p, false);
	exprcache_record(p, &tk, &v);
	if (v.kind != VAL_FLOAT)
		parse_error_at(p, v.pos, "expected a float, found a %s", val_kind_name(v.kind));
	return v.v[0];
}

vec3 parse_vector(struct parser *p)
{
	struct value v = parse_expression(p);
	if (v.kind == VAL_FLOAT || v.kind == VAL_VECTOR) {
		if (v.n > 3 && v.kind == VAL_VECTOR)
			parse_error_at(p, v.pos, "expected a 3-component vector, found a %d-component one", v.n);
		val_widen(&v, 3);
		return v3(v.v[0], v.v[1], v.v[2]);
	}
	parse_error_at(p, v.pos, "expected a vector, found a %s", val_kind_name(v.kind));
}

struct rgbft parse_color(struct parser *p)
{
	struct srcpos at = parse_peek(p)->pos;
	if (parse_is_kw(p, KW_COLOR) || parse_is_kw(p, KW_COLOUR))
		parse_advance(p);
	struct value c = parse_color_body(p, at);
	struct rgbft r = {c.v[0], c.v[1], c.v[2], c.v[3], c.v[4]};
	return r;
}

const char *parse_string(struct parser *p)
{
	const struct token *t = parse_peek(p);
	struct srcpos at = t->pos;
	if (t->kind == TOK_STRING) {
		const char *s = parse_charset_literal(p, t->str, at);
		parse_advance(p);
		return s;
	}
	/* Strings have no operators: one primary is the whole expression, and
	 * nothing after it is read. */
	struct value v = parse_primary(p);
	if (v.kind != VAL_STRING) {
		const char *kind = val_kind_name(v.kind);
		parse_drop(p, &v);
		parse_error_at(p, at, "expected a string, found a %s", kind);
	}
	return v.str;
}

const char *parse_intern(struct parser *p, const char *s, size_t n)
{
	return intern(p->names, s, n);
}

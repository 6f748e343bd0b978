/* func.c: user functions and splines. `function [(params)] { body }` is
 * compiled once into the stack code of scene/fn.h; declared floats are
 * folded in as constants, calls to other functions are linked directly.
 * Splines are parsed into sorted control points and evaluated on demand. */
#include "lang/parser.h"

#include "scene/fn.h"
#include "scene/texture.h"

#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---- compiling functions ---- */

static void free_fn_cb(void *f) { fn_unref(f); }

struct fcomp {
	struct parser *p;
	struct fn *f;
	const char *params[FN_MAX_PARAMS];
	int depth, maxdepth;    /* stack depth tracking */
};

static void emit(struct fcomp *c, enum fn_op op, int i, double k, int stack_change)
{
	struct fn_instr in;
	memset(&in, 0, sizeof in);
	in.op = (uint8_t)op;
	in.i = i;
	in.k = k;
	fn_emit(c->f, in);
	c->depth += stack_change;
	if (c->depth > c->maxdepth)
		c->maxdepth = c->depth;
	if (c->maxdepth >= FN_MAX_STACK)
		parse_error(c->p, "function too complex (its evaluation needs more than %d stack slots)", FN_MAX_STACK);
}

static void c_expr(struct fcomp *c);

static int param_index(struct fcomp *c, const char *name)
{
	for (int i = 0; i < c->f->nparams; i++)
		if (c->params[i] == name)
			return i;
	return -1;
}

static int coord_param_named(struct fcomp *c, const char *name)
{
	for (int i = 0; i < c->f->nparams; i++)
		if (c->params[i] && strcmp(c->params[i], name) == 0)
			return i;
	return -1;
}

/* x y z u v in a function body: the parameter of that name (u is x and v
 * is y); -1 if there is none. */
static int coord_param(struct fcomp *c, enum kw k)
{
	const char *name = kw_names[k];
	for (int i = 0; i < c->f->nparams; i++)
		if (c->params[i] && strcmp(c->params[i], name) == 0)
			return i;
	/* u and v are other names of x and y, both ways. */
	if (k == KW_U) return coord_param_named(c, "x");
	if (k == KW_V) return coord_param_named(c, "y");
	if (k == KW_X) return coord_param_named(c, "u");
	if (k == KW_Y) return coord_param_named(c, "v");
	return -1;
}

/* '(' expr {',' expr} ')' compiled in order; returns the count. */
static int c_args(struct fcomp *c)
{
	parse_expect(c->p, TOK_LPAREN);
	int n = 0;
	if (!parse_accept(c->p, TOK_RPAREN)) {
		do {
			c_expr(c);
			n++;
		} while (parse_accept(c->p, TOK_COMMA));
		parse_expect(c->p, TOK_RPAREN);
	}
	return n;
}

static void c_call_user(struct fcomp *c, struct fn *callee, const char *name, struct srcpos at)
{
	int n = c_args(c);
	if (n != callee->nparams)
		parse_error_at(c->p, at, "function %s takes %d argument%s, not %d", name, callee->nparams,
		               callee->nparams == 1 ? "" : "s", n);
	struct fn *f = c->f;
	f->callees = realloc(f->callees, (size_t)(f->ncallees + 1) * sizeof *f->callees);
	if (!f->callees) abort();
	f->callees[f->ncallees++] = fn_ref(callee);
	struct fn_instr in;
	memset(&in, 0, sizeof in);
	in.op = FN_USER;
	in.i = n;
	in.fn = callee;
	fn_emit(f, in);
	c->depth -= n - 1;
}

/* F(args).component for a colour- or vector-valued function F (function
 * { pigment { } }, { spline { } }, { transform { } }): F evaluated in
 * place, one component kept (POV-Ray accepts such a call in a function
 * body only with a component). */
static void c_call_vector(struct fcomp *c, struct fn *callee, const char *name, struct srcpos at)
{
	struct parser *p = c->p;
	int n = c_args(c);
	if (n != callee->nparams)
		parse_error_at(p, at, "function %s takes %d argument%s, not %d", name, callee->nparams,
		               callee->nparams == 1 ? "" : "s", n);
	if (!parse_accept(p, TOK_DOT))
		parse_error_at(p, at, "function %s gives a %s: name a component (.red, .green, .blue, .filter, "
		               ".transmit, .gray or .x, .y, .z, .t)", name, callee->pig ? "color" : "vector");
	const struct token *t = parse_peek(p);
	int i = -1;
	if (t->kind == TOK_KEYWORD) {
		switch (t->kw) {
		case KW_X: case KW_U: case KW_RED: i = 0; break;
		case KW_Y: case KW_V: case KW_GREEN: i = 1; break;
		case KW_Z: case KW_BLUE: i = 2; break;
		case KW_T: case KW_FILTER: i = 3; break;
		case KW_TRANSMIT: i = 4; break;
		case KW_GRAY: i = 5; break;
		default: break;
		}
	}
	if (i < 0)
		parse_expected(p, "a component after '.'");
	parse_advance(p);
	struct fn *f = c->f;
	f->callees = realloc(f->callees, (size_t)(f->ncallees + 1) * sizeof *f->callees);
	if (!f->callees) abort();
	f->callees[f->ncallees++] = fn_ref(callee);
	struct fn_instr in;
	memset(&in, 0, sizeof in);
	in.op = FN_VECTOR;
	in.i = i;
	in.fn = callee;
	fn_emit(f, in);
	c->depth -= n - 1;
}

static void c_primary(struct fcomp *c)
{
	struct parser *p = c->p;
	const struct token *t = parse_peek(p);
	struct srcpos at = t->pos;
	switch (t->kind) {
	case TOK_NUMBER:
		emit(c, FN_CONST, 0, t->num, 1);
		parse_advance(p);
		return;
	case TOK_LPAREN:
		parse_advance(p);
		c_expr(c);
		parse_expect(p, TOK_RPAREN);
		return;
	case TOK_IDENT: {
		const char *name = t->str;
		int pi = param_index(c, name);
		if (pi >= 0) {
			parse_advance(p);
			emit(c, FN_ARG, pi, 0, 1);
			return;
		}
		const struct value *v = parse_lookup(p, name);
		if (!v)
			parse_undefined(p, name);
		parse_advance(p);
		if (v->kind == VAL_ARRAY) {
			/* An element, F[K](x, y, z) or A[i]: as POV-Ray, the
			 * indices are read when the function is (ordinary
			 * expressions, so not of the function's parameters). */
			size_t idx = parse_array_index(p, v->arr, name, at);
			v = &v->arr->elems[idx];
			if (v->kind == VAL_NONE)
				parse_error_at(p, at, "element of array '%s' used before it was given a value", name);
		}
		if (v->kind == VAL_FLOAT) {
			emit(c, FN_CONST, 0, v->v[0], 1);
			return;
		}
		if (v->kind == VAL_FUNCTION && fn_is_vector(v->fn)) {
			c_call_vector(c, v->fn, name, at);
			return;
		}
		if (v->kind == VAL_FUNCTION) {
			c_call_user(c, v->fn, name, at);
			return;
		}
		parse_error_at(p, at, "%s'%s' is a %s; a function body can use floats and functions only",
		               p->prev.kind == TOK_RBRACKET ? "the element of array " : "", name, val_kind_name(v->kind));
	}
	case TOK_KEYWORD: {
		enum kw k = (enum kw)t->kw;
		if (k == KW_X || k == KW_Y || k == KW_Z || k == KW_U || k == KW_V) {
			int cp = coord_param(c, k);
			parse_advance(p);
			/* A coordinate the function has no parameter for is 0. */
			if (cp >= 0)
				emit(c, FN_ARG, cp, 0, 1);
			else
				emit(c, FN_CONST, 0, 0, 1);
			return;
		}
		double kval;
		switch (k) {
		case KW_PI: kval = M_PI; goto constant;
		case KW_TRUE: case KW_YES: case KW_ON: kval = 1; goto constant;
		case KW_FALSE: case KW_NO: case KW_OFF: kval = 0; goto constant;
		case KW_CLOCK: kval = p->o->clock; goto constant;
		case KW_IMAGE_WIDTH: kval = p->o->image_width; goto constant;
		case KW_IMAGE_HEIGHT: kval = p->o->image_height; goto constant;
		constant:
			parse_advance(p);
			emit(c, FN_CONST, 0, kval, 1);
			return;
		case KW_SUM: case KW_PROD: {
			/* sum(i, lo, hi, body) / prod(...): body is compiled as a
			 * function of this one's parameters plus i. */
			parse_advance(p);
			parse_expect(p, TOK_LPAREN);
			const struct token *vt = parse_peek(p);
			if (vt->kind != TOK_IDENT)
				parse_expected(p, "the loop variable's name");
			const char *var = vt->str;
			parse_advance(p);
			parse_expect(p, TOK_COMMA);
			c_expr(c);
			parse_expect(p, TOK_COMMA);
			c_expr(c);
			parse_expect(p, TOK_COMMA);
			if (c->f->nparams + 1 > FN_MAX_PARAMS)
				parse_error_at(p, at, "too many parameters and loop variables in one function");
			struct fcomp body = {.p = p, .f = fn_new(c->f->nparams + 1)};
			for (int i = 0; i < c->f->nparams; i++)
				body.params[i] = c->params[i];
			body.params[c->f->nparams] = var;
			int slot = parse_own(p, body.f, free_fn_cb);
			c_expr(&body);
			parse_expect(p, TOK_RPAREN);
			body.f->depth = body.maxdepth;
			parse_release(p, slot);
			struct fn *f = c->f;
			f->callees = realloc(f->callees, (size_t)(f->ncallees + 1) * sizeof *f->callees);
			if (!f->callees) abort();
			f->callees[f->ncallees++] = body.f; /* the reference parse_function gave */
			struct fn_instr in;
			memset(&in, 0, sizeof in);
			in.op = k == KW_SUM ? FN_SUM : FN_PROD;
			in.fn = body.f;
			fn_emit(f, in);
			c->depth -= 1;
			return;
		}
		case KW_MIN: case KW_MAX: {
			parse_advance(p);
			int n = c_args(c);
			if (n < 2)
				parse_error_at(p, at, "%s() needs at least two arguments", kw_names[k]);
			emit(c, k == KW_MIN ? FN_MIN : FN_MAX, n, 0, 1 - n);
			return;
		}
		case KW_SELECT: {
			parse_advance(p);
			int n = c_args(c);
			if (n != 3 && n != 4)
				parse_error_at(p, at, "select() takes 3 or 4 arguments, not %d", n);
			emit(c, FN_SELECT, n, 0, 1 - n);
			return;
		}
		default:
			break;
		}
		const struct math_fn *m = builtin_math_fn(k);
		if (m) {
			parse_advance(p);
			int n = c_args(c);
			if (n != m->nargs)
				parse_error_at(p, at, "%s() takes %d argument%s, not %d", kw_names[k], m->nargs,
				               m->nargs == 1 ? "" : "s", n);
			struct fn_instr in;
			memset(&in, 0, sizeof in);
			if (m->nargs == 1) {
				in.op = FN_CALL1;
				in.f1 = m->f1;
			} else {
				in.op = FN_CALL2;
				in.f2 = m->f2;
				c->depth--;
			}
			fn_emit(c->f, in);
			return;
		}
		break;
	}
	default:
		break;
	}
	parse_expected(p, "a number, a parameter, a function or '(' in the function body");
}

static void c_unary(struct fcomp *c)
{
	const struct token *t = parse_peek(c->p);
	if (t->kind == TOK_MINUS || t->kind == TOK_PLUS || t->kind == TOK_BANG) {
		enum tok_kind k = (enum tok_kind)t->kind;
		parse_advance(c->p);
		if (++c->p->expr_depth > (int)c->p->lim.expr_depth)
			parse_error(c->p, "expression nested too deeply (more than %d levels; lucent --limit expr-depth=N raises it)", (int)c->p->lim.expr_depth);
		c_unary(c);
		c->p->expr_depth--;
		if (k == TOK_MINUS)
			emit(c, FN_NEG, 0, 0, 0);
		else if (k == TOK_BANG)
			emit(c, FN_NOT, 0, 0, 0);
		return;
	}
	c_primary(c);
}

static int prec_of(enum tok_kind k, enum fn_op *op)
{
	switch (k) {
	case TOK_BAR: *op = FN_OR; return 1;
	case TOK_AMP: *op = FN_AND; return 2;
	case TOK_LT: *op = FN_LT; return 3;
	case TOK_LE: *op = FN_LE; return 3;
	case TOK_EQ: *op = FN_EQ; return 3;
	case TOK_GE: *op = FN_GE; return 3;
	case TOK_GT: *op = FN_GT; return 3;
	case TOK_NE: *op = FN_NE; return 3;
	case TOK_PLUS: *op = FN_ADD; return 4;
	case TOK_MINUS: *op = FN_SUB; return 4;
	case TOK_STAR: *op = FN_MUL; return 5;
	case TOK_SLASH: *op = FN_DIV; return 5;
	default: return 0;
	}
}

static void c_binary(struct fcomp *c, int min_prec)
{
	c_unary(c);
	for (;;) {
		enum fn_op op;
		int prec = prec_of((enum tok_kind)parse_peek(c->p)->kind, &op);
		if (prec == 0 || prec < min_prec)
			return;
		parse_advance(c->p);
		c_binary(c, prec + 1);
		emit(c, op, 0, 0, -1);
	}
}

/* expr := binary [ '?' expr ':' expr ] */
static void c_expr(struct fcomp *c)
{
	if (++c->p->expr_depth > (int)c->p->lim.expr_depth)
		parse_error(c->p, "expression nested too deeply (more than %d levels; lucent --limit expr-depth=N raises it)", (int)c->p->lim.expr_depth);
	c_binary(c, 1);
	if (parse_accept(c->p, TOK_QUESTION)) {
		int jz = fn_emit(c->f, (struct fn_instr){.op = FN_JZ});
		c->depth--;
		c_expr(c);
		int jmp = fn_emit(c->f, (struct fn_instr){.op = FN_JMP});
		c->depth--;
		parse_expect(c->p, TOK_COLON);
		c->f->code[jz].i = c->f->ncode;
		c_expr(c);
		c->f->code[jmp].i = c->f->ncode;
	}
	c->p->expr_depth--;
}

/* pattern '{' PATTERN '}' '}' | pigment '{' PIGMENT_BODY '}' '}' after a
 * function's '{': a function of x, y, z evaluating the pattern (its value)
 * or the pigment (its colour: the function is colour-valued). */
static struct fn *pattern_function(struct parser *p, int np)
{
	struct srcpos at = parse_peek(p)->pos;
	if (np != 3)
		parse_error_at(p, at, "a pattern or pigment function takes the 3 parameters x, y, z, not %d", np);
	struct fn *f = fn_new(3);
	int slot = parse_own(p, f, free_fn_cb);
	struct fn_instr in;
	memset(&in, 0, sizeof in);
	if (parse_is_kw(p, KW_PATTERN)) {
		parse_advance(p);
		f->pat = malloc(sizeof *f->pat);
		if (!f->pat) abort();
		*f->pat = pattern_make(PAT_NONE);
		parse_pattern_block(p, f->pat);
		in.op = FN_PATTERN;
		in.pat = f->pat;
	} else {
		f->pig = pigment_new();
		parse_pigment(p, &f->pig);
		in.op = FN_PIGMENT;
		in.pig = f->pig;
	}
	parse_expect(p, TOK_RBRACE);
	for (int i = 0; i < 3; i++)
		fn_emit(f, (struct fn_instr){.op = FN_ARG, .i = i});
	fn_emit(f, in);
	f->depth = 3;
	parse_release(p, slot);
	return f;
}

/* function { spline { } }: S(t) is the spline at t. */
static void spline_fn_eval(const void *data, const double *args, double out[5])
{
	struct value v = spline_eval(data, args[0], (struct srcpos){0});
	for (int i = 0; i < 5; i++)
		out[i] = i < v.n ? v.v[i] : 0;
}

static void spline_fn_free(void *data) { spline_unref(data); }

/* function { transform { } }: T(x, y, z) is the point <x, y, z> transformed. */
static void xform_fn_eval(const void *data, const double *args, double out[5])
{
	const struct xform *t = data;
	vec3 q = mat_point(&t->fwd, (vec3){args[0], args[1], args[2]});
	out[0] = q.x;
	out[1] = q.y;
	out[2] = q.z;
	out[3] = out[4] = 0;
}

/* spline '{' .. '}' '}' | transform '{' .. '}' '}' after a function's '{'
 * (the current token is the keyword): a vector-valued function of the
 * spline's parameter, or of x, y, z. POV-Ray allows no parameter list
 * here (params: whether one was given). */
static struct fn *vector_function(struct parser *p, bool params)
{
	bool spl = parse_is_kw(p, KW_SPLINE);
	if (params)
		parse_error(p, "a %s function takes no parameter list", spl ? "spline" : "transform");
	struct fn *f = fn_new(spl ? 1 : 3);
	int slot = parse_own(p, f, free_fn_cb);
	if (spl) {
		struct spline *s = parse_spline(p);
		f->vdata = s;
		f->vfree = spline_fn_free;
		f->veval = spline_fn_eval;
		f->vdim = s->dim;
	} else {
		f->vdata = parse_transform_value(p);
		f->vfree = free;
		f->veval = xform_fn_eval;
		f->vdim = 3;
	}
	parse_expect(p, TOK_RBRACE);
	parse_release(p, slot);
	return f;
}

static struct fn *function_body(struct parser *p, const char **params, int np, bool has_params);

/* function [ '(' param {',' param} ')' ] '{' ( expr | internal '(' N ')'
 *   | pattern '{' .. '}' | pigment '{' .. '}' | spline '{' .. '}'
 *   | transform '{' .. '}' ) '}'
 * The current token is 'function'. */
struct fn *parse_function(struct parser *p)
{
	parse_advance(p);
	const char *params[FN_MAX_PARAMS];
	int np = 0;
	bool has_params = parse_is(p, TOK_LPAREN);
	if (parse_accept(p, TOK_LPAREN)) {
		do {
			const struct token *t = parse_peek(p);
			if (np == FN_MAX_PARAMS)
				parse_error(p, "a function has at most %d parameters", FN_MAX_PARAMS);
			if (t->kind == TOK_IDENT)
				params[np++] = t->str;
			else if (t->kind == TOK_KEYWORD && (t->kw == KW_X || t->kw == KW_Y || t->kw == KW_Z ||
			                                    t->kw == KW_U || t->kw == KW_V))
				params[np++] = kw_names[t->kw];
			else
				parse_expected(p, "a parameter name");
			parse_advance(p);
		} while (parse_accept(p, TOK_COMMA));
		parse_expect(p, TOK_RPAREN);
	} else {
		params[0] = kw_names[KW_X];
		params[1] = kw_names[KW_Y];
		params[2] = kw_names[KW_Z];
		np = 3;
	}
	return function_body(p, params, np, has_params);
}

struct fn *parse_function_body(struct parser *p)
{
	const char *params[3] = {kw_names[KW_X], kw_names[KW_Y], kw_names[KW_Z]};
	return function_body(p, params, 3, false);
}

/* '{' ( expr | internal '(' N ')' | pattern '{' .. '}' | pigment '{' .. '}'
 *   | spline '{' .. '}' | transform '{' .. '}' ) '}'
 * with the given parameter names (has_params: a parameter list was written,
 * which spline and transform functions refuse). */
static struct fn *function_body(struct parser *p, const char **params, int np, bool has_params)
{
	parse_expect(p, TOK_LBRACE);
	if (parse_is_kw(p, KW_INTERNAL)) {
		struct srcpos at = parse_peek(p)->pos;
		parse_advance(p);
		parse_expect(p, TOK_LPAREN);
		double n = parse_float(p);
		parse_expect(p, TOK_RPAREN);
		parse_expect(p, TOK_RBRACE);
		/* Truncated to its number (as POV-Ray does), once it is known to
		 * fit an int. */
		int count = n > -1 && n < INT_MAX ? fn_internal_params((int)n) : -1;
		if (count < 0)
			parse_error_at(p, at, "there is no internal function %g", n);
		struct fn *f = fn_new(count);
		for (int i = 0; i < count; i++)
			fn_emit(f, (struct fn_instr){.op = FN_ARG, .i = i});
		fn_emit(f, (struct fn_instr){.op = FN_INTERNAL, .i = count, .k = (int)n});
		return f;
	}
	if (parse_is_kw(p, KW_PATTERN) || parse_is_kw(p, KW_PIGMENT))
		return pattern_function(p, np);
	if (parse_is_kw(p, KW_SPLINE) || parse_is_kw(p, KW_TRANSFORM))
		return vector_function(p, has_params);
	struct fcomp c = {.p = p, .f = fn_new(np)};
	for (int i = 0; i < np; i++)
		c.params[i] = params[i];
	int slot = parse_own(p, c.f, free_fn_cb);
	c_expr(&c);
	parse_expect(p, TOK_RBRACE);
	parse_release(p, slot);
	c.f->depth = c.maxdepth;
	return c.f;
}

struct value parse_call_function(struct parser *p, const struct fn *f, struct srcpos at)
{
	double args[FN_MAX_PARAMS];
	int n = 0;
	parse_expect(p, TOK_LPAREN);
	if (!parse_accept(p, TOK_RPAREN)) {
		do {
			struct value v = parse_expression(p);
			parse_need_float(p, &v, "a function argument");
			if (n == FN_MAX_PARAMS)
				parse_error_at(p, v.pos, "too many function arguments");
			args[n++] = v.v[0];
		} while (parse_accept(p, TOK_COMMA));
		parse_expect(p, TOK_RPAREN);
	}
	if (n != f->nparams)
		parse_error_at(p, at, "this function takes %d argument%s, not %d", f->nparams, f->nparams == 1 ? "" : "s", n);
	struct value r;
	if (f->pig) {
		double c[5];
		fn_eval_color(f, args, c);
		r = val_vector(5, c, VAL_COLOR, at);
	} else if (f->vdim > 0) {
		double c[5];
		fn_eval_vector(f, args, c);
		r = val_vector(f->vdim, c, f->vdim == 5 ? VAL_COLOR : VAL_VECTOR, at);
	} else {
		r = val_float(fn_eval(f, args), at);
	}
	/* A sum() or prod() left off by Ctrl-C (fn_set_stop): stop here, at the
	 * call, rather than at the parser's next step. */
	if (p->o->stop && *p->o->stop)
		parse_step(p, at, false);
	return r;
}

/* ---- splines ---- */

static void free_spline_cb(void *s) { spline_unref(s); }

static void natural_prepare(struct spline *s)
{
	int n = s->n;
	free(s->d2);
	s->d2 = calloc((size_t)n * 5, sizeof *s->d2);
	if (!s->d2) abort();
	if (n < 3)
		return;
	double *u = malloc((size_t)n * sizeof *u);
	if (!u) abort();
	for (int c = 0; c < 5; c++) {
		/* The tridiagonal system of a natural cubic spline (second
		 * derivative 0 at both ends), solved by elimination. */
		double *d2 = s->d2;
		d2[c] = 0;
		u[0] = 0;
		for (int i = 1; i < n - 1; i++) {
			double sig = (s->t[i] - s->t[i - 1]) / (s->t[i + 1] - s->t[i - 1]);
			double q = sig * d2[(i - 1) * 5 + c] + 2;
			d2[i * 5 + c] = (sig - 1) / q;
			double dy1 = (s->v[(i + 1) * 5 + c] - s->v[i * 5 + c]) / (s->t[i + 1] - s->t[i]);
			double dy0 = (s->v[i * 5 + c] - s->v[(i - 1) * 5 + c]) / (s->t[i] - s->t[i - 1]);
			u[i] = (6 * (dy1 - dy0) / (s->t[i + 1] - s->t[i - 1]) - sig * u[i - 1]) / q;
		}
		d2[(n - 1) * 5 + c] = 0;
		for (int i = n - 2; i >= 0; i--)
			d2[i * 5 + c] = d2[i * 5 + c] * d2[(i + 1) * 5 + c] + u[i];
	}
	free(u);
}

/* spline { [IDENT] [type] { T ',' V [','] } } ; the current token is 'spline'. */
struct spline *parse_spline(struct parser *p)
{
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct spline *s = calloc(1, sizeof *s);
	if (!s) abort();
	s->refs = 1;
	int slot = parse_own(p, s, free_spline_cb);
	int cap = 0;
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_IDENT) {
		const struct value *v = parse_lookup(p, t->str);
		if (v && v->kind == VAL_SPLINE) {
			const struct spline *o = v->spl;
			s->kind = o->kind;
			s->dim = o->dim;
			s->n = o->n;
			cap = o->n;
			s->t = malloc((size_t)(cap ? cap : 1) * sizeof *s->t);
			s->v = malloc((size_t)(cap ? cap : 1) * 5 * sizeof *s->v);
			if (!s->t || !s->v) abort();
			memcpy(s->t, o->t, (size_t)o->n * sizeof *s->t);
			memcpy(s->v, o->v, (size_t)o->n * 5 * sizeof *s->v);
			parse_advance(p);
		}
	}
	for (;;) {
		if (parse_accept_kw(p, KW_LINEAR_SPLINE)) { s->kind = SPLINE_LINEAR; continue; }
		if (parse_accept_kw(p, KW_QUADRATIC_SPLINE)) { s->kind = SPLINE_QUADRATIC; continue; }
		if (parse_accept_kw(p, KW_CUBIC_SPLINE)) { s->kind = SPLINE_CUBIC; continue; }
		if (parse_accept_kw(p, KW_NATURAL_SPLINE)) { s->kind = SPLINE_NATURAL; continue; }
		if (parse_accept(p, TOK_RBRACE))
			break;
		double tv = parse_float(p);
		parse_expect(p, TOK_COMMA);
		struct value v = parse_expression(p);
		parse_need_numeric(p, &v, "a spline point");
		parse_accept(p, TOK_COMMA);
		if (v.kind == VAL_FLOAT)
			val_widen(&v, 5); /* a float fills every component */
		else if (v.n > s->dim)
			s->dim = v.n;
		/* Sorted insertion; an equal parameter replaces the point. */
		int i = 0;
		while (i < s->n && s->t[i] < tv)
			i++;
		if (i < s->n && s->t[i] == tv) {
			for (int c = 0; c < 5; c++)
				s->v[i * 5 + c] = c < v.n ? v.v[c] : 0;
			continue;
		}
		if (s->n == cap) {
			cap = cap ? cap * 2 : 8;
			s->t = realloc(s->t, (size_t)cap * sizeof *s->t);
			s->v = realloc(s->v, (size_t)cap * 5 * sizeof *s->v);
			if (!s->t || !s->v) abort();
		}
		memmove(s->t + i + 1, s->t + i, (size_t)(s->n - i) * sizeof *s->t);
		memmove(s->v + (i + 1) * 5, s->v + i * 5, (size_t)(s->n - i) * 5 * sizeof *s->v);
		s->t[i] = tv;
		for (int c = 0; c < 5; c++)
			s->v[i * 5 + c] = c < v.n ? v.v[c] : 0;
		s->n++;
	}
	if (s->dim < 2)
		s->dim = 2; /* a spline of floats gives 2-component vectors */
	if (s->kind == SPLINE_NATURAL)
		natural_prepare(s);
	parse_release(p, slot);
	return s;
}

/* The Lagrange polynomial through points i0..i0+k-1, at t, component c. */
static double lagrange(const struct spline *s, int i0, int k, double t, int c)
{
	double r = 0;
	for (int j = i0; j < i0 + k; j++) {
		double w = 1;
		for (int m = i0; m < i0 + k; m++)
			if (m != j)
				w *= (t - s->t[m]) / (s->t[j] - s->t[m]);
		r += w * s->v[j * 5 + c];
	}
	return r;
}

struct value spline_eval_as(const struct spline *s, double t, int kind, struct srcpos at)
{
	if (kind < 0 || (enum spline_kind)kind == s->kind)
		return spline_eval(s, t, at);
	struct spline tmp = *s;
	tmp.kind = (enum spline_kind)kind;
	tmp.d2 = NULL;
	if (tmp.kind == SPLINE_NATURAL)
		natural_prepare(&tmp);
	struct value r = spline_eval(&tmp, t, at);
	free(tmp.d2);
	return r;
}

struct value spline_eval(const struct spline *s, double t, struct srcpos at)
{
	double out[5] = {0};
	int n = s->n;
	if (n == 0)
		return val_vector(s->dim ? s->dim : 3, out, VAL_VECTOR, at);
	int lo = 0, hi = n - 1;
	if (s->kind == SPLINE_CUBIC && n >= 4) {
		lo = 1;
		hi = n - 2;
	}
	if (t <= s->t[lo] || n == 1) {
		memcpy(out, &s->v[lo * 5], sizeof out);
	} else if (t >= s->t[hi]) {
		memcpy(out, &s->v[hi * 5], sizeof out);
	} else {
		int i = lo;
		while (i + 1 < hi && t >= s->t[i + 1])
			i++;
		for (int c = 0; c < 5; c++) {
			switch (s->kind) {
			case SPLINE_LINEAR: {
				double f = (t - s->t[i]) / (s->t[i + 1] - s->t[i]);
				out[c] = s->v[i * 5 + c] * (1 - f) + s->v[(i + 1) * 5 + c] * f;
				break;
			}
			case SPLINE_QUADRATIC: {
				/* The parabola through the point before, this one and the
				 * next (the first three on the first segment). */
				int i0 = i == 0 ? 0 : i - 1;
				if (n < 3)
					i0 = 0;
				out[c] = lagrange(s, i0, n < 3 ? n : 3, t, c);
				break;
			}
			case SPLINE_CUBIC: {
				if (n < 4) {
					out[c] = lagrange(s, 0, n, t, c);
					break;
				}
				/* Hermite between i and i+1; the tangent at a point is
				 * the mean of the slopes of the chords on either side
				 * (what POV-Ray evaluates, measured). */
				double h = s->t[i + 1] - s->t[i];
				double f = (t - s->t[i]) / h;
				double p0 = s->v[(i - 1) * 5 + c], p1 = s->v[i * 5 + c];
				double p2 = s->v[(i + 1) * 5 + c], p3 = s->v[(i + 2) * 5 + c];
				double s01 = (p1 - p0) / (s->t[i] - s->t[i - 1]);
				double s12 = (p2 - p1) / h;
				double s23 = (p3 - p2) / (s->t[i + 2] - s->t[i + 1]);
				double m1 = 0.5 * (s01 + s12) * h;
				double m2 = 0.5 * (s12 + s23) * h;
				double f2 = f * f, f3 = f2 * f;
				out[c] = (2 * f3 - 3 * f2 + 1) * p1 + (f3 - 2 * f2 + f) * m1 + (-2 * f3 + 3 * f2) * p2 + (f3 - f2) * m2;
				break;
			}
			case SPLINE_NATURAL: {
				double h = s->t[i + 1] - s->t[i];
				double a = (s->t[i + 1] - t) / h, b = (t - s->t[i]) / h;
				out[c] = a * s->v[i * 5 + c] + b * s->v[(i + 1) * 5 + c] +
				         ((a * a * a - a) * s->d2[i * 5 + c] + (b * b * b - b) * s->d2[(i + 1) * 5 + c]) * h * h / 6;
				break;
			}
			}
		}
	}
	return val_vector(s->dim, out, s->dim == 5 ? VAL_COLOR : VAL_VECTOR, at);
}

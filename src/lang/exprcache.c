/* exprcache.c: compiled float expressions (see exprcache.h).
 *
 * The first time parse_expression starts at a token of a file or macro
 * body, the expression is parsed the ordinary way and where it ended is
 * recorded. If it was a float expression read straight from that token
 * array (no directive or macro call ran meanwhile), its tokens are
 * compiled into a small stack program: numbers, float identifiers,
 * operators, ?:, and the float built-ins. Later evaluations at that token
 * run the program and jump to the recorded end, which is what a loop body
 * or a macro called many times needs: nothing is read twice.
 *
 * The program holds no values, only names: identifiers are looked up at
 * every run, so scoping is the ordinary parser's. Whenever a run meets
 * something the program cannot vouch for (an identifier that is not a
 * plain float, a division by zero, a result that is not finite, a rand()
 * stream that does not exist), it gives up before changing anything and
 * the ordinary parser reads the expression, giving the same value or the
 * same error as always. */
#include "lang/exprcache.h"

#include "lang/parser.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum xop {
	X_NUM,      /* push k */
	X_VAR,      /* push the float bound to name */
	X_NEG, X_NOT,
	X_ADD, X_SUB, X_MUL, X_DIV,
	X_OR, X_AND, X_LT, X_LE, X_EQ, X_GE, X_GT, X_NE, /* in enum parse_cmp's order */
	X_JZ,       /* pop; if false, jump to i */
	X_JMP,      /* jump to i */
	X_F1, X_F2, /* built-in math function of 1 or 2 arguments */
	X_MIN, X_MAX, /* pop i values, push the least / greatest */
	X_RAND,     /* pop a stream number, push its next value */
	X_VEC,      /* pop i floats, push the vector <...> of them */
	X_CONST,    /* push the vector constant kv (x, y, z, t, u, v) */
	X_COLOR,    /* make the top a colour as the keyword i (rgb, rgbf, ...) does */
	/* Fused forms of common pairs (one dispatch instead of two): */
	X_ADDK, X_SUBK, X_MULK, X_DIVK, /* top := top op k (also k + top, k * top) */
	X_KSUB, X_KDIV, /* top := k op top */
	X_RANDV,    /* push the next value of the stream bound to name: rand(V) */
};

struct xinstr {
	uint8_t op;
	int32_t i;
	double k;
	const char *name;
	const struct math_fn *fn;
	double kv[5];                /* X_CONST */
	int kn;
	const struct value *bound;   /* X_VAR: the binding found when name's bucket
	                              * in p->lookgen was at generation gen */
	unsigned long gen;
	uint16_t bucket;             /* X_VAR: sym_gen_bucket(name) */
};

enum xstate { XS_COMPILED, XS_NO };

struct xentry {
	const struct token *key;     /* the expression's first token */
	uint8_t state;
	uint8_t ctx;                 /* the context it was compiled in: rel_ok, and 2
	                              * when read as an operand (exprcache_try_operand) */
	uint32_t len;                /* its tokens */
	struct xinstr *code;
	int ncode;
	int depth;                   /* deepest stack */
	bool scalar;                 /* only float operations, but for a final vector
	                              * literal (and colour keyword): run_scalar can run it */
	uint8_t tail_vec;            /* that final <...>'s size, or 0 */
	int body;                    /* scalar: the instructions before that literal */
};

struct exprcache {
	struct xentry *slots;        /* open addressing on key */
	size_t cap, count;
};

enum { XSTACK = 64, XMAX_CODE = 256 };

struct exprcache *exprcache_new(void)
{
	struct exprcache *c = calloc(1, sizeof *c);
	if (!c) abort();
	c->cap = 256;
	c->slots = calloc(c->cap, sizeof *c->slots);
	if (!c->slots) abort();
	return c;
}

void exprcache_free(struct exprcache *c)
{
	if (!c)
		return;
	for (size_t i = 0; i < c->cap; i++)
		free(c->slots[i].code);
	free(c->slots);
	free(c);
}

static size_t slot_of(const struct exprcache *c, const struct token *key)
{
	uintptr_t h = (uintptr_t)key;
	h ^= h >> 17;
	h *= 0x9E3779B97F4A7C15u;
	return (size_t)(h >> 7) & (c->cap - 1);
}

static struct xentry *find(struct exprcache *c, const struct token *key)
{
	for (size_t i = slot_of(c, key);; i = (i + 1) & (c->cap - 1)) {
		struct xentry *e = &c->slots[i];
		if (e->key == key || !e->key)
			return e;
	}
}

static struct xentry *insert(struct exprcache *c, const struct token *key)
{
	if (2 * (c->count + 1) > c->cap) {
		struct xentry *old = c->slots;
		size_t ocap = c->cap;
		c->cap *= 2;
		c->slots = calloc(c->cap, sizeof *c->slots);
		if (!c->slots) abort();
		for (size_t i = 0; i < ocap; i++)
			if (old[i].key)
				*find(c, old[i].key) = old[i];
		free(old);
	}
	struct xentry *e = find(c, key);
	if (!e->key) {
		e->key = key;
		c->count++;
	}
	return e;
}

/* ---- where the parser stands ---- */

static bool same_token(const struct token *a, const struct token *b)
{
	return a->kind == b->kind && a->pos.file == b->pos.file && a->pos.line == b->pos.line &&
	       a->pos.col == b->pos.col;
}

/* The index in the top frame's tokens of the next token the parser will
 * read, or -1 if the lookahead did not come straight from there. */
static inline long next_index(const struct parser *p)
{
	const struct frame *f = &p->frames[p->nframes - 1];
	if (!p->have_cur)
		return f->pos < f->end ? (long)f->pos : -1;
	/* A '#' sentinel is looked at in place; other lookaheads were taken. */
	if (f->pos <= f->end && same_token(&p->cur, &f->toks[f->pos]) && p->cur.kind == TOK_HASH)
		return (long)f->pos;
	if (f->pos > 0 && same_token(&p->cur, &f->toks[f->pos - 1]))
		return (long)f->pos - 1;
	return -1;
}

/* An expression that reaches the end of its frame (the last one of a
 * macro body) goes on in the frame below if what follows there continues
 * it (`M() + 1`). Its compiled form is the whole expression only when the
 * next token below cannot. */
static bool ends_in_caller(const struct parser *p)
{
	if (p->nframes < 2)
		return true; /* the main file ends with EOF */
	const struct frame *c = &p->frames[p->nframes - 2];
	if (c->pos >= c->end)
		return false;
	switch (c->toks[c->pos].kind) {
	case TOK_SEMI: case TOK_COMMA: case TOK_RPAREN: case TOK_RBRACE: case TOK_RBRACKET:
		return true;
	default:
		return false;
	}
}

/* ---- compiling ---- */

struct compiler {
	const struct parser *p;
	const struct token *t;       /* the expression's tokens */
	uint32_t n, at;
	struct xinstr code[XMAX_CODE];
	int ncode, sp, depth;
	bool ok;
};

static void emit(struct compiler *c, enum xop op, int32_t i, double k, int stack)
{
	if (c->ncode == XMAX_CODE) {
		c->ok = false;
		return;
	}
	struct xinstr in = {.op = (uint8_t)op, .i = i, .k = k};
	c->code[c->ncode++] = in;
	c->sp += stack;
	if (c->sp > c->depth)
		c->depth = c->sp;
	if (c->depth > XSTACK)
		c->ok = false;
}

static const struct token *peek(const struct compiler *c)
{
	static const struct token end = {.kind = TOK_EOF};
	return c->at < c->n ? &c->t[c->at] : &end;
}

static bool accept(struct compiler *c, enum tok_kind k)
{
	if (peek(c)->kind != k)
		return false;
	c->at++;
	return true;
}

static void cond(struct compiler *c, bool rel, bool inv);
static void binary(struct compiler *c, int min_prec, bool rel, bool inv);

/* The binary operators of expr.c's binop, with the same strengths; inside
 * a vector literal (inv) a '>' closes it. */
static int binop(enum tok_kind k, bool rel, bool inv, enum xop *op)
{
	switch (k) {
	case TOK_PLUS: *op = X_ADD; return 4;
	case TOK_MINUS: *op = X_SUB; return 4;
	case TOK_STAR: *op = X_MUL; return 5;
	case TOK_SLASH: *op = X_DIV; return 5;
	default: break;
	}
	if (!rel)
		return 0;
	switch (k) {
	case TOK_BAR: *op = X_OR; return 2;
	case TOK_AMP: *op = X_AND; return 2;
	case TOK_LT: *op = X_LT; return 3;
	case TOK_LE: *op = X_LE; return 3;
	case TOK_EQ: *op = X_EQ; return 3;
	case TOK_GE: *op = X_GE; return 3;
	case TOK_GT: *op = X_GT; return inv ? 0 : 3;
	case TOK_NE: *op = X_NE; return 3;
	default: return 0;
	}
}

/* '(' args ')' of a built-in: n float arguments (n < 0: two or more). */
static int args(struct compiler *c, int n)
{
	if (!accept(c, TOK_LPAREN)) {
		c->ok = false;
		return 0;
	}
	int got = 0;
	do {
		cond(c, true, false);
		got++;
	} while (c->ok && accept(c, TOK_COMMA));
	if (!accept(c, TOK_RPAREN) || (n >= 0 && got != n) || (n < 0 && got < 2))
		c->ok = false;
	return got;
}

static void emit_const(struct compiler *c, int n, double a, double b, double d, double e)
{
	emit(c, X_CONST, 0, 0, 1);
	if (!c->ok)
		return;
	struct xinstr *in = &c->code[c->ncode - 1];
	in->kn = n;
	in->kv[0] = a;
	in->kv[1] = b;
	in->kv[2] = d;
	in->kv[3] = e;
}

static void primary(struct compiler *c, bool rel)
{
	const struct token *t = peek(c);
	switch (t->kind) {
	case TOK_NUMBER:
		c->at++;
		emit(c, X_NUM, 0, t->num, 1);
		return;
	case TOK_LPAREN:
		c->at++;
		cond(c, true, false);
		if (!accept(c, TOK_RPAREN))
			c->ok = false;
		return;
	case TOK_LT: {
		/* '<' cond { ',' cond } '>': components read in the context's
		 * rel, with '>' closing (expr.c's parse_vector_literal). */
		c->at++;
		int n = 0;
		for (;;) {
			cond(c, rel, true);
			n++;
			if (!c->ok)
				break;
			if (accept(c, TOK_COMMA))
				continue;
			if (peek(c)->kind == TOK_GT || n >= 5)
				break;
			/* Commas may be left out: the next component begins here
			 * (the ordinary parser decides; any token that cannot begin
			 * one fails the compile). */
		}
		if (!accept(c, TOK_GT) || n < 2 || n > 5)
			c->ok = false;
		emit(c, X_VEC, n, 0, 1 - n);
		return;
	}
	case TOK_IDENT: {
		c->at++;
		enum tok_kind next = (enum tok_kind)peek(c)->kind;
		/* Calls, elements and components need the full parser. */
		if (next == TOK_LPAREN || next == TOK_LBRACKET || next == TOK_DOT) {
			c->ok = false;
			return;
		}
		emit(c, X_VAR, 0, 0, 1);
		c->code[c->ncode - 1].name = t->str;
		c->code[c->ncode - 1].bucket = (uint16_t)sym_gen_bucket(t->str);
		return;
	}
	case TOK_KEYWORD:
		break;
	default:
		c->ok = false;
		return;
	}
	c->at++;
	enum kw k = (enum kw)t->kw;
	if (peek(c)->kind == TOK_DOT) {
		c->ok = false;
		return;
	}
	switch (k) {
	case KW_X: emit_const(c, 3, 1, 0, 0, 0); return;
	case KW_Y: emit_const(c, 3, 0, 1, 0, 0); return;
	case KW_Z: emit_const(c, 3, 0, 0, 1, 0); return;
	case KW_T: emit_const(c, 4, 0, 0, 0, 1); return;
	case KW_U: emit_const(c, 2, 1, 0, 0, 0); return;
	case KW_V: emit_const(c, 2, 0, 1, 0, 0); return;
	case KW_SRGB: case KW_SRGBF: case KW_SRGBT: case KW_SRGBFT:
		/* sRGB colours depend on assumed_gamma, which may change or not
		 * be set yet: the full parser reads them every time. */
		c->ok = false;
		return;
	case KW_RGB: case KW_RGBF: case KW_RGBT: case KW_RGBFT: {
		/* expr.c's parse_color_keyword: a binary of strength 4, then
		 * optional component keywords, which need the full parser. */
		binary(c, 4, false, false);
		emit(c, X_COLOR, (int32_t)k, 0, 0);
		const struct token *nt = peek(c);
		if (nt->kind == TOK_KEYWORD && (nt->kw == KW_RED || nt->kw == KW_GREEN || nt->kw == KW_BLUE ||
		                                nt->kw == KW_FILTER || nt->kw == KW_TRANSMIT))
			c->ok = false;
		return;
	}
	case KW_PI: emit(c, X_NUM, 0, M_PI, 1); return;
	case KW_TRUE: case KW_YES: case KW_ON: emit(c, X_NUM, 0, 1, 1); return;
	case KW_FALSE: case KW_NO: case KW_OFF: emit(c, X_NUM, 0, 0, 1); return;
	case KW_MIN: case KW_MAX: {
		int n = args(c, -1);
		emit(c, k == KW_MIN ? X_MIN : X_MAX, n, 0, 1 - n);
		return;
	}
	case KW_RAND: {
		int at = c->ncode;
		args(c, 1);
		if (c->ok && c->ncode == at + 1 && c->code[at].op == X_VAR)
			c->code[at].op = X_RANDV; /* rand(V): the variable's stream */
		else
			emit(c, X_RAND, 0, 0, 0);
		return;
	}
	default:
		break;
	}
	const struct math_fn *m = builtin_math_fn(k);
	if (!m) {
		c->ok = false;
		return;
	}
	args(c, m->nargs);
	emit(c, m->nargs == 1 ? X_F1 : X_F2, 0, 0, 1 - m->nargs);
	if (c->ok)
		c->code[c->ncode - 1].fn = m;
}

static void unary(struct compiler *c, bool rel)
{
	const struct token *t = peek(c);
	if (t->kind == TOK_MINUS || t->kind == TOK_PLUS || t->kind == TOK_BANG) {
		c->at++;
		unary(c, rel);
		if (!c->ok)
			return;
		if (t->kind == TOK_MINUS)
			emit(c, X_NEG, 0, 0, 0);
		else if (t->kind == TOK_BANG)
			emit(c, X_NOT, 0, 0, 0);
		return;
	}
	primary(c, rel);
}

/* The fused instruction for `x op k` (k_left: `k op x`), or -1. Addition
 * and multiplication give the same result either way round (also on
 * vectors: a float operand fills every component). */
static int fused(enum xop op, bool k_left)
{
	switch (op) {
	case X_ADD: return X_ADDK;
	case X_MUL: return X_MULK;
	case X_SUB: return k_left ? X_KSUB : X_SUBK;
	case X_DIV: return k_left ? X_KDIV : X_DIVK;
	default: return -1;
	}
}

static void binary(struct compiler *c, int min_prec, bool rel, bool inv)
{
	int start = c->ncode;
	unary(c, rel);
	while (c->ok) {
		enum xop op;
		int prec = binop((enum tok_kind)peek(c)->kind, rel, inv, &op);
		if (prec == 0 || prec < min_prec)
			return;
		c->at++;
		/* A lone number on either side becomes the operand of a fused
		 * instruction (40 * rand(R) - 20: two instructions fewer). The
		 * left one is taken back before the right side is compiled, so
		 * no jump target moves. */
		bool k_left = fused(op, true) >= 0 && c->ncode == start + 1 && c->code[start].op == X_NUM;
		double k = k_left ? c->code[start].k : 0;
		if (k_left) {
			c->ncode--;
			c->sp--;
		}
		int right = c->ncode;
		binary(c, prec + 1, rel, inv);
		if (!c->ok)
			return;
		if (k_left) {
			emit(c, (enum xop)fused(op, true), 0, k, 0);
		} else if (fused(op, false) >= 0 && c->ncode == right + 1 && c->code[right].op == X_NUM) {
			k = c->code[right].k;
			c->ncode--;
			c->sp--;
			emit(c, (enum xop)fused(op, false), 0, k, 0);
		} else {
			emit(c, op, 0, 0, -1);
		}
	}
}

static void cond(struct compiler *c, bool rel, bool inv)
{
	binary(c, 1, rel, inv);
	if (!c->ok || !rel || peek(c)->kind != TOK_QUESTION)
		return;
	c->at++;
	int jz = c->ncode;
	emit(c, X_JZ, 0, 0, -1);
	cond(c, rel, inv);
	if (!accept(c, TOK_COLON)) {
		c->ok = false;
		return;
	}
	int jmp = c->ncode;
	emit(c, X_JMP, 0, 0, -1);
	if (!c->ok)
		return;
	c->code[jz].i = c->ncode;
	cond(c, rel, inv);
	if (c->ok)
		c->code[jmp].i = c->ncode;
}

static void compile(struct xentry *e, const struct parser *p, const struct token *t, uint32_t n, bool rel, bool operand)
{
	struct compiler c = {.p = p, .t = t, .n = n, .ok = true};
	cond(&c, rel, false);
	e->state = XS_NO;
	if (!c.ok || c.at != n)
		return;
	e->code = malloc((size_t)c.ncode * sizeof *e->code);
	if (!e->code) abort();
	memcpy(e->code, c.code, (size_t)c.ncode * sizeof *e->code);
	e->ncode = c.ncode;
	e->depth = c.depth;
	e->len = n;
	e->ctx = (uint8_t)(rel | operand << 1);
	/* A vector literal at the very end (a colour keyword may follow)
	 * takes the floats its components left on the stack: run_scalar
	 * gathers them. Everything before must be float operations. */
	int body = c.ncode;
	if (body > 0 && c.code[body - 1].op == X_COLOR)
		body--;
	e->tail_vec = 0;
	if (body > 0 && c.code[body - 1].op == X_VEC) {
		e->tail_vec = (uint8_t)c.code[body - 1].i;
		body--;
	} else if (body != c.ncode) {
		body = -1; /* a colour keyword on a float: run does it */
	}
	e->scalar = body >= 0;
	e->body = body;
	for (int i = 0; i < body; i++)
		if (c.code[i].op == X_CONST || c.code[i].op == X_VEC || c.code[i].op == X_COLOR)
			e->scalar = false;
	e->state = XS_COMPILED;
}

/* ---- running ---- */

/* A value on the stack: a float, vector (2..5) or colour (5). */
struct xval {
	double v[5];
	int n;
	enum val_kind kind;
};

static double compare(enum xop op, double x, double y)
{
	return parse_compare((enum parse_cmp)(op - X_OR), x, y);
}

/* a := a op b, with expr.c's widening (a float fills every component,
 * a vector is padded with zeros); false on division by zero. */
static bool binary_op(enum xop op, struct xval *a, const struct xval *b)
{
	if (a->kind == VAL_FLOAT && b->kind == VAL_FLOAT) {
		double x = a->v[0], y = b->v[0];
		switch (op) {
		case X_ADD: a->v[0] = x + y; return true;
		case X_SUB: a->v[0] = x - y; return true;
		case X_MUL: a->v[0] = x * y; return true;
		case X_DIV:
			if (y == 0)
				return false;
			a->v[0] = x / y;
			return true;
		default: a->v[0] = compare(op, x, y); return true;
		}
	}
	int n = a->n > b->n ? a->n : b->n;
	double bv[5];
	for (int i = 0; i < n; i++) {
		if (i >= a->n)
			a->v[i] = a->kind == VAL_FLOAT ? a->v[0] : 0;
		bv[i] = i < b->n ? b->v[i] : b->kind == VAL_FLOAT ? b->v[0] : 0;
	}
	a->kind = (a->kind == VAL_COLOR || b->kind == VAL_COLOR) ? VAL_COLOR : n > 1 ? VAL_VECTOR : VAL_FLOAT;
	a->n = n;
	for (int i = 0; i < n; i++) {
		switch (op) {
		case X_ADD: a->v[i] += bv[i]; break;
		case X_SUB: a->v[i] -= bv[i]; break;
		case X_MUL: a->v[i] *= bv[i]; break;
		case X_DIV:
			if (bv[i] == 0)
				return false;
			a->v[i] /= bv[i];
			break;
		default: a->v[i] = compare(op, a->v[i], bv[i]); break;
		}
	}
	if (a->kind == VAL_COLOR)
		a->n = 5;
	return true;
}

/* expr.c's parse_color_keyword on an evaluated operand. */
static void make_color(enum kw k, struct xval *x)
{
	double c[5];
	parse_keyword_color(k, x->v, x->n, x->kind == VAL_FLOAT, c);
	memcpy(x->v, c, sizeof c);
	x->n = 5;
	x->kind = VAL_COLOR;
}

enum { XRAND_UNDO = 32 };

/* The value an X_VAR names. The binding found last time stands while the
 * name's lookup generation holds (sym.h: no binding of the name added or
 * removed, entered or left the scope chain, and no table grew), so a
 * loop's variables stay found across the macro calls in its body. A
 * by-reference parameter is followed every time (the array element it
 * names can move). */
static inline const struct value *var_value(struct parser *p, struct xinstr *in)
{
	const struct value *v = in->bound;
	if (v && in->gen == p->lookgen.name[in->bucket])
		return v;
	v = parse_binding(p, in->name);
	in->bound = v && v->kind != VAL_ALIAS ? v : NULL;
	in->gen = p->lookgen.name[in->bucket];
	if (v && v->kind == VAL_ALIAS)
		v = parse_lookup(p, in->name);
	return v;
}

/* Run a scalar entry (only floats on the stack): the same operations as
 * run's, without vectors, so each step is a few instructions. False, with
 * nothing changed, where a variable is not a plain float or run would
 * fail; the caller then tries run. */
static bool run_scalar(struct parser *p, struct xentry *e, struct xval *out)
{
	double st[XSTACK];
	struct { long i; uint32_t state; } undo[XRAND_UNDO];
	int sp = 0, nundo = 0;
	int body = e->body;
	for (int pc = 0; pc < body; pc++) {
		struct xinstr *in = &e->code[pc];
		switch ((enum xop)in->op) {
		case X_NUM: st[sp++] = in->k; break;
		case X_VAR: {
			const struct value *v = var_value(p, in);
			if (!v || v->kind != VAL_FLOAT || v->deprecated)
				goto not_float;
			st[sp++] = v->v[0];
			break;
		}
		case X_NEG: st[sp - 1] = -st[sp - 1]; break;
		case X_NOT: st[sp - 1] = !parse_truthy(st[sp - 1]); break;
		case X_ADD: sp--; st[sp - 1] += st[sp]; break;
		case X_SUB: sp--; st[sp - 1] -= st[sp]; break;
		case X_MUL: sp--; st[sp - 1] *= st[sp]; break;
		case X_DIV:
			sp--;
			if (st[sp] == 0)
				goto fail;
			st[sp - 1] /= st[sp];
			break;
		case X_LT: case X_LE: case X_EQ: case X_GE: case X_GT: case X_NE: case X_AND: case X_OR:
			sp--;
			st[sp - 1] = compare((enum xop)in->op, st[sp - 1], st[sp]);
			break;
		case X_JZ:
			if (!parse_truthy(st[--sp]))
				pc = in->i - 1;
			break;
		case X_JMP: pc = in->i - 1; break;
		case X_F1:
			st[sp - 1] = in->fn->f1(st[sp - 1]);
			if (!isfinite(st[sp - 1]))
				goto fail;
			break;
		case X_F2:
			sp--;
			st[sp - 1] = in->fn->f2(st[sp - 1], st[sp]);
			if (!isfinite(st[sp - 1]))
				goto fail;
			break;
		case X_MIN: case X_MAX: {
			int n = in->i;
			sp -= n;
			double acc = st[sp];
			for (int i = 1; i < n; i++) {
				double x = st[sp + i];
				acc = in->op == X_MIN ? (x < acc ? x : acc) : (x > acc ? x : acc);
			}
			st[sp++] = acc;
			break;
		}
		case X_ADDK: st[sp - 1] += in->k; break;
		case X_SUBK: st[sp - 1] -= in->k; break;
		case X_MULK: st[sp - 1] *= in->k; break;
		case X_DIVK:
			if (in->k == 0)
				goto fail;
			st[sp - 1] /= in->k;
			break;
		case X_KSUB: st[sp - 1] = in->k - st[sp - 1]; break;
		case X_KDIV:
			if (st[sp - 1] == 0)
				goto fail;
			st[sp - 1] = in->k / st[sp - 1];
			break;
		case X_RANDV: {
			const struct value *v = var_value(p, in);
			if (!v || v->kind != VAL_FLOAT || v->deprecated)
				goto not_float;
			st[sp++] = v->v[0];
		}
			/* fall through */
		case X_RAND: {
			if (!parse_rng_stream(p, st[sp - 1]) || nundo == XRAND_UNDO)
				goto fail;
			long i = (long)st[sp - 1];
			undo[nundo].i = i;
			undo[nundo++].state = p->rng[i];
			p->rng[i] = p->rng[i] * 1812433253u + 12345u;
			st[sp - 1] = p->rng[i] / 4294967295.0;
			break;
		}
		default:
			goto fail;
		}
	}
	/* The end: a float, or the final vector literal. */
	if (!e->tail_vec) {
		out->v[0] = st[0];
		out->n = 1;
		out->kind = VAL_FLOAT;
		return true;
	}
	int n = e->tail_vec;
	for (int k = 0; k < 5; k++)
		out->v[k] = k < n ? st[k] : 0;
	out->n = n;
	out->kind = VAL_VECTOR;
	if (body + 1 < e->ncode)
		make_color((enum kw)e->code[body + 1].i, out);
	return true;
not_float:
	/* A variable holds a vector or colour (a macro's parameter P in
	 * sphere { P, R }): run takes this entry from now on. */
	e->scalar = false;
fail:
	while (nundo > 0) {
		nundo--;
		p->rng[undo[nundo].i] = undo[nundo].state;
	}
	return false;
}

/* Run e; false (and nothing changed) where the ordinary parser must. The
 * rand() streams it advanced are put back when it gives up. */
static bool run(struct parser *p, struct xentry *e, bool want_float, struct xval *out)
{
	struct xval st[XSTACK];
	struct { long i; uint32_t state; } undo[XRAND_UNDO];
	int sp = 0, nundo = 0;
	st[0].kind = VAL_NONE;
	for (int pc = 0; pc < e->ncode; pc++) {
		struct xinstr *in = &e->code[pc];
		switch ((enum xop)in->op) {
		case X_NUM:
			st[sp].v[0] = in->k;
			st[sp].n = 1;
			st[sp++].kind = VAL_FLOAT;
			break;
		case X_CONST:
			memcpy(st[sp].v, in->kv, sizeof in->kv);
			st[sp].n = in->kn;
			st[sp++].kind = VAL_VECTOR;
			break;
		case X_VAR: {
			const struct value *v = var_value(p, in);
			if (!v || !val_is_numeric(v) || v->deprecated)
				goto fail;
			memcpy(st[sp].v, v->v, sizeof v->v);
			st[sp].n = v->n;
			st[sp++].kind = v->kind;
			break;
		}
		case X_NEG: case X_NOT: {
			struct xval *a = &st[sp - 1];
			for (int i = 0; i < a->n; i++)
				a->v[i] = in->op == X_NEG ? -a->v[i] : !parse_truthy(a->v[i]);
			break;
		}
		case X_ADD: case X_SUB: case X_MUL: case X_DIV:
		case X_LT: case X_LE: case X_EQ: case X_GE: case X_GT: case X_NE: case X_AND: case X_OR:
			sp--;
			if (!binary_op((enum xop)in->op, &st[sp - 1], &st[sp]))
				goto fail;
			break;
		case X_JZ:
			sp--;
			if (st[sp].kind != VAL_FLOAT)
				goto fail;
			if (!parse_truthy(st[sp].v[0]))
				pc = in->i - 1;
			break;
		case X_JMP: pc = in->i - 1; break;
		case X_F1:
			if (st[sp - 1].kind != VAL_FLOAT)
				goto fail;
			st[sp - 1].v[0] = in->fn->f1(st[sp - 1].v[0]);
			if (!isfinite(st[sp - 1].v[0]))
				goto fail;
			break;
		case X_F2:
			sp--;
			if (st[sp - 1].kind != VAL_FLOAT || st[sp].kind != VAL_FLOAT)
				goto fail;
			st[sp - 1].v[0] = in->fn->f2(st[sp - 1].v[0], st[sp].v[0]);
			if (!isfinite(st[sp - 1].v[0]))
				goto fail;
			break;
		case X_MIN: case X_MAX: {
			int n = in->i;
			sp -= n;
			if (st[sp].kind != VAL_FLOAT)
				goto fail;
			double acc = st[sp].v[0];
			for (int i = 1; i < n; i++) {
				if (st[sp + i].kind != VAL_FLOAT)
					goto fail;
				double x = st[sp + i].v[0];
				acc = in->op == X_MIN ? (x < acc ? x : acc) : (x > acc ? x : acc);
			}
			st[sp++].v[0] = acc;
			break;
		}
		case X_ADDK: case X_SUBK: case X_MULK: case X_DIVK: case X_KSUB: case X_KDIV: {
			static const enum xop base[] = {
				[X_ADDK] = X_ADD, [X_SUBK] = X_SUB, [X_MULK] = X_MUL,
				[X_DIVK] = X_DIV, [X_KSUB] = X_SUB, [X_KDIV] = X_DIV,
			};
			struct xval k = {.v = {in->k}, .n = 1, .kind = VAL_FLOAT};
			if (in->op == X_KSUB || in->op == X_KDIV) {
				struct xval x = st[sp - 1];
				st[sp - 1] = k;
				if (!binary_op(base[in->op], &st[sp - 1], &x))
					goto fail;
			} else if (!binary_op(base[in->op], &st[sp - 1], &k)) {
				goto fail;
			}
			break;
		}
		case X_RANDV: {
			const struct value *v = var_value(p, in);
			if (!v || v->kind != VAL_FLOAT || v->deprecated)
				goto fail;
			st[sp].v[0] = v->v[0];
			st[sp].n = 1;
			st[sp++].kind = VAL_FLOAT;
		}
			/* fall through */
		case X_RAND: {
			if (st[sp - 1].kind != VAL_FLOAT || !parse_rng_stream(p, st[sp - 1].v[0]) || nundo == XRAND_UNDO)
				goto fail;
			long i = (long)st[sp - 1].v[0];
			undo[nundo].i = i;
			undo[nundo++].state = p->rng[i];
			p->rng[i] = p->rng[i] * 1812433253u + 12345u;
			st[sp - 1].v[0] = p->rng[i] / 4294967295.0;
			break;
		}
		case X_VEC: {
			int n = in->i;
			sp -= n;
			struct xval r = {.n = n, .kind = VAL_VECTOR};
			for (int i = 0; i < n; i++) {
				if (st[sp + i].kind != VAL_FLOAT)
					goto fail;
				r.v[i] = st[sp + i].v[0];
			}
			for (int i = n; i < 5; i++)
				r.v[i] = 0;
			st[sp++] = r;
			break;
		}
		case X_COLOR:
			make_color((enum kw)in->i, &st[sp - 1]);
			break;
		}
	}
	if (want_float && st[0].kind != VAL_FLOAT)
		goto fail;
	*out = st[0];
	for (int i = out->n; i < 5; i++)
		out->v[i] = 0;
	return true;
fail:
	while (nundo > 0) {
		nundo--;
		p->rng[undo[nundo].i] = undo[nundo].state;
	}
	return false;
}

/* Where the compiled form may run: the parser at a token whose expression
 * is compiled for this context. Returns the entry, or NULL. */
static inline __attribute__((always_inline)) struct xentry *ready(struct parser *p, struct exprcache_ticket *tk, long *index,
                                                                  bool operand)
{
	tk->key = NULL;
	if (!p->xcache)
		return NULL;
	long i = next_index(p);
	if (i < 0)
		return NULL;
	struct frame *f = &p->frames[p->nframes - 1];
	const struct token *key = &f->toks[i];
	if (key->kind == TOK_HASH)
		return NULL;
	struct xentry *e = find(p->xcache, key);
	if (!e->key) {
		/* First time here: the caller parses and tells us how it went. */
		tk->key = key;
		tk->toks = f->toks;
		tk->limit = f->end;
		tk->frame = p->nframes;
		tk->events = p->events;
		tk->rel_ok = p->rel_ok;
		tk->operand = operand;
		return NULL;
	}
	if (e->state != XS_COMPILED || e->ctx != (p->rel_ok | operand << 1) || (size_t)i + e->len > f->end)
		return NULL;
	if ((size_t)i + e->len == f->end && !ends_in_caller(p))
		return NULL;
	*index = i;
	return e;
}

/* Move the parser past the expression that began at index i. */
static void skip(struct parser *p, long i, const struct xentry *e)
{
	struct frame *f = &p->frames[p->nframes - 1];
	f->pos = (size_t)i + e->len;
	p->have_cur = false;
	p->prev = f->toks[f->pos - 1];
}

static bool try_value(struct parser *p, struct value *out, struct exprcache_ticket *tk, bool operand)
{
	long i;
	struct xentry *e = ready(p, tk, &i, operand);
	if (!e)
		return false;
	struct xval x;
	if (!(e->scalar && run_scalar(p, e, &x)) && !run(p, e, false, &x))
		return false;
	for (int k = x.n; k < 5; k++)
		x.v[k] = 0;
	/* Fill *out in place: building the value on the stack and copying
	 * it costs more than the whole program (store-forwarding stalls). */
	memset(out, 0, sizeof *out);
	out->kind = x.kind;
	out->n = x.n;
	out->pos = e->key->pos;
	memcpy(out->v, x.v, sizeof x.v);
	skip(p, i, e);
	return true;
}

bool exprcache_try(struct parser *p, struct value *out, struct exprcache_ticket *tk)
{
	return try_value(p, out, tk, false);
}

bool exprcache_try_operand(struct parser *p, struct value *out, struct exprcache_ticket *tk)
{
	return try_value(p, out, tk, true);
}

bool exprcache_try_float(struct parser *p, double *out, struct exprcache_ticket *tk)
{
	long i;
	struct xentry *e = ready(p, tk, &i, false);
	if (!e)
		return false;
	struct xval x;
	if (!(e->scalar && !e->tail_vec && run_scalar(p, e, &x)) && !run(p, e, true, &x))
		return false;
	*out = x.v[0];
	skip(p, i, e);
	return true;
}

void exprcache_record(struct parser *p, const struct exprcache_ticket *tk, const struct value *v)
{
	if (!tk->key)
		return;
	struct xentry *e = insert(p->xcache, tk->key);
	e->state = XS_NO;
	if (!val_is_numeric(v))
		return;
	long end;
	if (p->events == tk->events && p->nframes == tk->frame && p->frames[p->nframes - 1].toks == tk->toks) {
		const struct frame *f = &p->frames[p->nframes - 1];
		end = next_index(p);
		if (end < 0 && !p->have_cur && f->pos == f->end)
			end = (long)f->end;
	} else if (p->events == tk->events + 1 && p->nframes == tk->frame - 1) {
		/* The lookahead after the expression left the frame it ended:
		 * the last expression of a macro body or a file. */
		end = (long)tk->limit;
	} else {
		return;
	}
	long start = tk->key - tk->toks;
	if (start < 0 || (size_t)start >= tk->limit || end <= start)
		return;
	compile(e, p, tk->key, (uint32_t)(end - start), tk->rel_ok, tk->operand);
}

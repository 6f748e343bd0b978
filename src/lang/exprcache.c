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
	X_LT, X_LE, X_EQ, X_GE, X_GT, X_NE, X_AND, X_OR,
	X_JZ,       /* pop; if false, jump to i */
	X_JMP,      /* jump to i */
	X_F1, X_F2, /* built-in math function of 1 or 2 arguments */
	X_MIN, X_MAX, /* pop i values, push the least / greatest */
	X_RAND,     /* pop a stream number, push its next value */
};

struct xinstr {
	uint8_t op;
	int32_t i;
	double k;
	const char *name;
	const struct math_fn *fn;
	const struct value *bound;   /* X_VAR: the binding found when bindgen was `gen` */
	unsigned long gen;
};

enum xstate { XS_COMPILED, XS_NO };

struct xentry {
	const struct token *key;     /* the expression's first token */
	uint8_t state;
	bool rel_ok;                 /* the context it was compiled in */
	uint32_t len;                /* its tokens */
	struct xinstr *code;
	int ncode;
	int depth;                   /* deepest stack */
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
static long next_index(const struct parser *p)
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

static void cond(struct compiler *c, bool rel);

/* The binary operators of expr.c's binop, with the same strengths. */
static int binop(enum tok_kind k, bool rel, enum xop *op)
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
	case TOK_GT: *op = X_GT; return 3;
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
		cond(c, true);
		got++;
	} while (c->ok && accept(c, TOK_COMMA));
	if (!accept(c, TOK_RPAREN) || (n >= 0 && got != n) || (n < 0 && got < 2))
		c->ok = false;
	return got;
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
		cond(c, true);
		if (!accept(c, TOK_RPAREN))
			c->ok = false;
		return;
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
	case KW_PI: emit(c, X_NUM, 0, M_PI, 1); return;
	case KW_TRUE: case KW_YES: case KW_ON: emit(c, X_NUM, 0, 1, 1); return;
	case KW_FALSE: case KW_NO: case KW_OFF: emit(c, X_NUM, 0, 0, 1); return;
	case KW_MIN: case KW_MAX: {
		int n = args(c, -1);
		emit(c, k == KW_MIN ? X_MIN : X_MAX, n, 0, 1 - n);
		return;
	}
	case KW_RAND:
		args(c, 1);
		emit(c, X_RAND, 0, 0, 0);
		return;
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
		if (t->kind == TOK_MINUS)
			emit(c, X_NEG, 0, 0, 0);
		else if (t->kind == TOK_BANG)
			emit(c, X_NOT, 0, 0, 0);
		return;
	}
	primary(c, rel);
}

static void binary(struct compiler *c, int min_prec, bool rel)
{
	unary(c, rel);
	while (c->ok) {
		enum xop op;
		int prec = binop((enum tok_kind)peek(c)->kind, rel, &op);
		if (prec == 0 || prec < min_prec)
			return;
		c->at++;
		binary(c, prec + 1, rel);
		emit(c, op, 0, 0, -1);
	}
}

static void cond(struct compiler *c, bool rel)
{
	binary(c, 1, rel);
	if (!c->ok || !rel || peek(c)->kind != TOK_QUESTION)
		return;
	c->at++;
	int jz = c->ncode;
	emit(c, X_JZ, 0, 0, -1);
	cond(c, rel);
	if (!accept(c, TOK_COLON)) {
		c->ok = false;
		return;
	}
	int jmp = c->ncode;
	emit(c, X_JMP, 0, 0, -1);
	if (!c->ok)
		return;
	c->code[jz].i = c->ncode;
	cond(c, rel);
	if (c->ok)
		c->code[jmp].i = c->ncode;
}

static void compile(struct xentry *e, const struct parser *p, const struct token *t, uint32_t n, bool rel)
{
	struct compiler c = {.p = p, .t = t, .n = n, .ok = true};
	cond(&c, rel);
	e->state = XS_NO;
	if (!c.ok || c.at != n)
		return;
	e->code = malloc((size_t)c.ncode * sizeof *e->code);
	if (!e->code) abort();
	memcpy(e->code, c.code, (size_t)c.ncode * sizeof *e->code);
	e->ncode = c.ncode;
	e->depth = c.depth;
	e->len = n;
	e->rel_ok = rel;
	e->state = XS_COMPILED;
}

/* ---- running ---- */

/* POV-Ray's tolerance for equality and truth, as in expr.c. */
#define EQ_EPSILON 1e-10
static bool truthy(double x) { return fabs(x) > EQ_EPSILON; }

/* Run e; false (and nothing changed) where the ordinary parser must. */
static bool run(struct parser *p, struct xentry *e, double *out)
{
	double st[XSTACK];
	int sp = 0;
	for (int pc = 0; pc < e->ncode; pc++) {
		struct xinstr *in = &e->code[pc];
		switch ((enum xop)in->op) {
		case X_NUM: st[sp++] = in->k; break;
		case X_VAR: {
			/* The binding found last time stands while no binding has
			 * been added or removed and no frame entered or left. A
			 * by-reference parameter is followed every time (the array
			 * element it names can move). */
			const struct value *v = in->bound;
			if (!v || in->gen != p->bindgen) {
				v = parse_binding(p, in->name);
				in->bound = v && v->kind != VAL_ALIAS ? v : NULL;
				in->gen = p->bindgen;
				if (v && v->kind == VAL_ALIAS)
					v = parse_lookup(p, in->name);
			}
			if (!v || v->kind != VAL_FLOAT || v->deprecated)
				return false;
			st[sp++] = v->v[0];
			break;
		}
		case X_NEG: st[sp - 1] = -st[sp - 1]; break;
		case X_NOT: st[sp - 1] = !truthy(st[sp - 1]); break;
		case X_ADD: sp--; st[sp - 1] += st[sp]; break;
		case X_SUB: sp--; st[sp - 1] -= st[sp]; break;
		case X_MUL: sp--; st[sp - 1] *= st[sp]; break;
		case X_DIV:
			sp--;
			if (st[sp] == 0)
				return false;
			st[sp - 1] /= st[sp];
			break;
		case X_LT: sp--; st[sp - 1] = st[sp - 1] < st[sp]; break;
		case X_LE: sp--; st[sp - 1] = st[sp - 1] <= st[sp] + EQ_EPSILON; break;
		case X_EQ: sp--; st[sp - 1] = fabs(st[sp - 1] - st[sp]) <= EQ_EPSILON; break;
		case X_GE: sp--; st[sp - 1] = st[sp - 1] >= st[sp] - EQ_EPSILON; break;
		case X_GT: sp--; st[sp - 1] = st[sp - 1] > st[sp]; break;
		case X_NE: sp--; st[sp - 1] = fabs(st[sp - 1] - st[sp]) > EQ_EPSILON; break;
		case X_AND: sp--; st[sp - 1] = truthy(st[sp - 1]) && truthy(st[sp]); break;
		case X_OR: sp--; st[sp - 1] = truthy(st[sp - 1]) || truthy(st[sp]); break;
		case X_JZ:
			sp--;
			if (!truthy(st[sp]))
				pc = in->i - 1;
			break;
		case X_JMP: pc = in->i - 1; break;
		case X_F1:
			st[sp - 1] = in->fn->f1(st[sp - 1]);
			if (!isfinite(st[sp - 1]))
				return false;
			break;
		case X_F2:
			sp--;
			st[sp - 1] = in->fn->f2(st[sp - 1], st[sp]);
			if (!isfinite(st[sp - 1]))
				return false;
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
		case X_RAND: {
			/* The only instruction with an effect: it runs last among
			 * those that can fail only if the program has no later
			 * failure point, which compile_ok_rand guarantees. */
			long i = (long)st[sp - 1];
			if (i < 0 || i >= p->nrng)
				return false;
			p->rng[i] = p->rng[i] * 1812433253u + 12345u;
			st[sp - 1] = p->rng[i] / 4294967295.0;
			break;
		}
		}
	}
	*out = st[0];
	return true;
}

/* A program with rand() must not give up after a rand() has advanced its
 * stream (the ordinary parser would advance it again): allow rand() only
 * where nothing after it can fail. */
static bool rand_is_safe(const struct xentry *e)
{
	bool seen = false;
	for (int pc = 0; pc < e->ncode; pc++) {
		enum xop op = (enum xop)e->code[pc].op;
		if (op == X_RAND)
			seen = true;
		else if (seen && (op == X_VAR || op == X_DIV || op == X_F1 || op == X_F2))
			return false;
	}
	return true;
}

bool exprcache_try(struct parser *p, struct value *out, struct exprcache_ticket *tk)
{
	double x;
	const struct token *key;
	if (!exprcache_try_float(p, &x, &key, tk))
		return false;
	/* Fill *out in place: building the value on the stack and copying
	 * it costs more than the whole program (store-forwarding stalls). */
	memset(out, 0, sizeof *out);
	out->kind = VAL_FLOAT;
	out->n = 1;
	out->pos = key->pos;
	out->v[0] = x;
	return true;
}

bool exprcache_try_float(struct parser *p, double *out, const struct token **start, struct exprcache_ticket *tk)
{
	tk->key = NULL;
	if (!p->xcache)
		return false;
	long i = next_index(p);
	if (i < 0)
		return false;
	struct frame *f = &p->frames[p->nframes - 1];
	const struct token *key = &f->toks[i];
	if (key->kind == TOK_HASH)
		return false;
	struct xentry *e = find(p->xcache, key);
	if (!e->key) {
		/* First time here: the caller parses and tells us how it went. */
		tk->key = key;
		tk->toks = f->toks;
		tk->limit = f->end;
		tk->frame = p->nframes;
		tk->events = p->events;
		tk->rel_ok = p->rel_ok;
		return false;
	}
	if (e->state != XS_COMPILED || e->rel_ok != p->rel_ok || (size_t)i + e->len > f->end)
		return false;
	if ((size_t)i + e->len == f->end && !ends_in_caller(p))
		return false;
	if (!run(p, e, out))
		return false;
	*start = key;
	f->pos = (size_t)i + e->len;
	p->have_cur = false;
	p->prev = f->toks[f->pos - 1];
	return true;
}

void exprcache_record(struct parser *p, const struct exprcache_ticket *tk, const struct value *v)
{
	if (!tk->key)
		return;
	struct xentry *e = insert(p->xcache, tk->key);
	e->state = XS_NO;
	if (v->kind != VAL_FLOAT)
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
	compile(e, p, tk->key, (uint32_t)(end - start), tk->rel_ok);
	if (e->state == XS_COMPILED && !rand_is_safe(e)) {
		free(e->code);
		e->code = NULL;
		e->state = XS_NO;
	}
}

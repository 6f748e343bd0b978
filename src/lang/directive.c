/* directive.c: the directives (#declare, #if, #while, #macro, ...), run by
 * the token stream whenever it meets a '#'. Conditionals and loops are
 * driven by a stack of open blocks (struct cond); a false branch is skipped
 * by scanning raw tokens, and a loop jumps back by token index. Nothing is
 * lexed again. */
#include "lang/parser.h"

#include "lang/intern.h"
#include "lang/ustr.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static struct frame *top(struct parser *p) { return &p->frames[p->nframes - 1]; }

static _Noreturn void raw_expected(struct parser *p, const struct token *t, const char *what)
{
	char buf[128];
	parse_error_at(p, t->pos, "expected %s, found %s", what, lex_describe(t, buf, sizeof buf));
}

/* The next raw token, which must be of kind k. */
static struct token raw_expect(struct parser *p, enum tok_kind k, const char *what)
{
	struct token t = parse_raw(p);
	if (t.kind != k)
		raw_expected(p, &t, what);
	return t;
}

/* A condition is true when it is not zero; POV-Ray counts values within
 * 1e-10 of zero as zero, to forgive round-off. */

/* A float inside a directive's parentheses, where comparisons and
 * logical operators bind (see struct parser's rel_ok). */
static double inner_float(struct parser *p)
{
	bool rel = parse_set_rel(p, true);
	double v = parse_float(p);
	p->rel_ok = rel;
	return v;
}

/* '(' FLOAT ')', reading nothing after the ')'. A condition read before
 * (a #while's, every iteration) runs whole from its compiled form,
 * parentheses included. */
static double paren_float(struct parser *p)
{
	double v;
	struct exprcache_ticket tk;
	if (exprcache_try_float(p, &v, &tk))
		return v;
	parse_expect(p, TOK_LPAREN);
	v = inner_float(p);
	parse_expect(p, TOK_RPAREN);
	struct value r = {.kind = VAL_FLOAT, .n = 1, .v = {v}};
	exprcache_record(p, &tk, &r);
	return v;
}

/* ---- skipping ---- */

enum { STOP_END = 1, STOP_ELSE = 2, STOP_CASE = 4 };

/* Skip raw tokens of the top frame up to a directive at nesting depth 0
 * whose kind is in `stop` (#end always stops, at depth 0 after `depth`
 * more #ends). Returns its keyword, leaving the frame just past it. An
 * unclosed block is reported at `open`. */
static enum kw skip_block(struct parser *p, int stop, int depth, struct srcpos open, const char *what)
{
	struct frame *f = top(p);
	while (f->pos + 1 < f->end) {
		const struct token *t = &f->toks[f->pos++];
		if (t->kind != TOK_HASH)
			continue;
		const struct token *k = &f->toks[f->pos];
		if (k->kind != TOK_KEYWORD)
			continue;
		switch (k->kw) {
		case KW_IF: case KW_IFDEF: case KW_IFNDEF: case KW_SWITCH: case KW_WHILE: case KW_FOR: case KW_MACRO:
			depth++;
			break;
		case KW_END:
			if (depth == 0) {
				f->pos++;
				return KW_END;
			}
			depth--;
			break;
		case KW_ELSE: case KW_ELSEIF:
			if (depth == 0 && (stop & STOP_ELSE)) {
				f->pos++;
				return (enum kw)k->kw;
			}
			break;
		case KW_CASE: case KW_RANGE:
			if (depth == 0 && (stop & STOP_CASE)) {
				f->pos++;
				return (enum kw)k->kw;
			}
			break;
		default:
			break;
		}
	}
	parse_error_at(p, open, "%s is never closed by #end%s", what,
	               f->kind == FRAME_MACRO ? " inside its macro" : " in its file");
}

/* The '#' of the directive skip_block stopped at. */
static struct srcpos skipped_to(struct parser *p)
{
	const struct frame *f = top(p);
	return f->toks[f->pos - 2].pos;
}

/* ---- the block stack ---- */

static struct cond *push_cond(struct parser *p, enum cond_kind k, struct srcpos pos)
{
	if (p->nconds == MAX_CONDS)
		parse_error_at(p, pos, "#if, #switch, #while and #for nested too deeply (more than %d)", MAX_CONDS);
	struct cond *c = &p->conds[p->nconds++];
	memset(c, 0, sizeof *c);
	c->serial = ++p->cond_serial;
	c->kind = k;
	c->frame = p->nframes - 1;
	c->pos = pos;
	return c;
}

/* The innermost open block of this frame, or NULL. */
static struct cond *top_cond(struct parser *p)
{
	if (p->nconds == 0 || p->conds[p->nconds - 1].frame != p->nframes - 1)
		return NULL;
	return &p->conds[p->nconds - 1];
}

/* Directives run wherever their tokens are, inside an expression too: an
 * #end among an #elseif's or a #case's operands closes the block they
 * belong to (and with it, at a macro's end, the macro's frame). After
 * such operands, is the innermost block still the one numbered `serial`
 * in this frame? If not, the operands' position is an error. */
static void cond_intact(struct parser *p, unsigned serial, struct srcpos at, const char *what, const char *block)
{
	const struct cond *c = top_cond(p);
	if (!c || c->serial != serial)
		parse_error_at(p, at, "the operands of %s closed the %s they belong to (a directive among them)", what,
		               block);
}

/* ---- #if, #ifdef, #ifndef, #else, #elseif ---- */

/* After a false condition: find the branch to run, or the #end. */
static void skip_false_branch(struct parser *p, struct srcpos open)
{
	unsigned serial = top_cond(p)->serial;
	for (;;) {
		enum kw k = skip_block(p, STOP_ELSE, 0, open, "#if");
		if (k == KW_END) {
			p->nconds--;
			return;
		}
		if (k == KW_ELSE)
			return;
		struct srcpos at = skipped_to(p);
		bool yes = parse_truthy(paren_float(p)); /* #elseif */
		cond_intact(p, serial, at, "#elseif", "#if");
		if (yes)
			return;
	}
}

static void dir_if(struct parser *p, struct srcpos at)
{
	bool c = parse_truthy(paren_float(p));
	push_cond(p, COND_IF, at);
	if (!c)
		skip_false_branch(p, at);
}

/* #ifdef ( IDENT ) / #ifndef ( IDENT ) */
static void dir_ifdef(struct parser *p, struct srcpos at, bool want)
{
	raw_expect(p, TOK_LPAREN, "'(' after #ifdef");
	/* The identifier itself is read raw: naming a macro must not call it. */
	const struct frame *f = top(p);
	const struct token *t = f->pos < f->end ? &f->toks[f->pos] : NULL;
	bool defined;
	if (t && t->kind == TOK_IDENT && f->pos + 1 < f->end && f->toks[f->pos + 1].kind == TOK_RPAREN) {
		defined = parse_lookup(p, t->str) != NULL;
		top(p)->pos++;
	} else {
		defined = parse_defined(p);
	}
	parse_expect(p, TOK_RPAREN);
	push_cond(p, COND_IF, at);
	if (defined != want)
		skip_false_branch(p, at);
}

/* #else / #elseif met while running a branch: the rest is skipped. In a
 * #switch, #else is one more case, reached by falling through. */
static void dir_else(struct parser *p, struct srcpos at, enum kw k)
{
	struct cond *c = top_cond(p);
	if (c && c->kind == COND_SWITCH && k == KW_ELSE) {
		c->matched = true;
		return;
	}
	if (!c || c->kind != COND_IF)
		parse_error_at(p, at, "#%s without an open #if", kw_names[k]);
	skip_block(p, STOP_END, 0, c->pos, "#if");
	p->nconds--;
}

/* ---- #switch, #case, #range, #break ---- */

static bool case_matches(struct parser *p, enum kw k, double v)
{
	if (k == KW_CASE)
		return fabs(v - paren_float(p)) < 1e-10;
	parse_expect(p, TOK_LPAREN);
	double lo = inner_float(p);
	parse_expect(p, TOK_COMMA);
	double hi = inner_float(p);
	parse_expect(p, TOK_RPAREN);
	return v >= lo && v <= hi;
}

/* case_matches for the switch c (the innermost block), which its
 * operands must leave open; `at`: the directive's '#'. */
static bool case_matches_in(struct parser *p, enum kw k, struct cond *c, struct srcpos at)
{
	unsigned serial = c->serial;
	bool yes = case_matches(p, k, c->value);
	cond_intact(p, serial, at, k == KW_CASE ? "#case" : "#range", "#switch");
	return yes;
}

/* Skip to the next clause of the switch c that applies, or its #end. */
static void skip_to_case(struct parser *p, struct cond *c)
{
	for (;;) {
		enum kw k = skip_block(p, STOP_CASE | STOP_ELSE, 0, c->pos, "#switch");
		if (k == KW_END) {
			p->nconds--;
			return;
		}
		if (k == KW_ELSE || case_matches_in(p, k, c, skipped_to(p))) {
			c->matched = true;
			return;
		}
	}
}

static void dir_switch(struct parser *p, struct srcpos at)
{
	double v = paren_float(p);
	struct cond *c = push_cond(p, COND_SWITCH, at);
	c->value = v;
	/* Tokens before the first #case are parsed, as POV-Ray does. */
}

static void dir_case(struct parser *p, struct srcpos at, enum kw k)
{
	struct cond *c = top_cond(p);
	if (!c || c->kind != COND_SWITCH)
		parse_error_at(p, at, "#%s outside a #switch", kw_names[k]);
	if (c->matched) {
		/* Falling through from the clause above: skip the operands. */
		(void)case_matches_in(p, k, c, at);
		return;
	}
	if (case_matches_in(p, k, c, at))
		c->matched = true;
	else
		skip_to_case(p, c);
}

/* #break leaves the innermost #switch, #while or #for of this frame. */
static void dir_break(struct parser *p, struct srcpos at)
{
	int i = p->nconds - 1;
	while (i >= 0 && p->conds[i].frame == p->nframes - 1 && p->conds[i].kind == COND_IF)
		i--;
	if (i < 0 || p->conds[i].frame != p->nframes - 1) {
		/* Outside any loop or switch, #break ends the macro it is in. */
		struct frame *f = top(p);
		if (f->kind != FRAME_MACRO)
			parse_error_at(p, at, "#break outside a #switch, #while, #for or macro");
		p->nconds = f->nconds;
		f->pos = f->end;
		return;
	}
	int inner = p->nconds - 1 - i;
	struct srcpos open = p->conds[i].pos;
	p->nconds = i;
	skip_block(p, STOP_END, inner, open, "the block of this #break");
}

/* ---- #while, #for, #end ---- */

static void dir_while(struct parser *p, struct srcpos at, size_t hash)
{
	if (parse_truthy(paren_float(p))) {
		struct cond *c = push_cond(p, COND_WHILE, at);
		c->loop = hash;
	} else {
		skip_block(p, STOP_END, 0, at, "#while");
	}
}

/* Assign a #for loop variable: like #local, so a loop in a macro does
 * not leak its variable (POV-Ray's behaviour). */
static void declare_float(struct parser *p, const char *name, double x)
{
	struct value v = {.kind = VAL_FLOAT, .n = 1};
	v.v[0] = x;
	parse_assign(p, name, true, v);
}

/* Does a #for loop run with its variable at i? POV-Ray allows 1e-10 past
 * the end, whatever the step (measured: #for (Y, 0.78, 0.93, 0.01) runs
 * 16 times though the summed Y ends 2e-16 past 0.93; with the end moved
 * 0.9e-10 lower it still does, with 1.1e-10 it runs 15; the same for
 * steps 1, 100, 0.0001 and downwards). */
static bool for_continues(double i, double end, double step)
{
	return step > 0 ? i <= end + 1e-10 : i >= end - 1e-10;
}

/* #for ( IDENT , START , END [, STEP] ) */
static void dir_for(struct parser *p, struct srcpos at)
{
	raw_expect(p, TOK_LPAREN, "'(' after #for");
	struct token id = parse_raw(p);
	if (id.kind != TOK_IDENT)
		raw_expected(p, &id, "the loop variable's name");
	raw_expect(p, TOK_COMMA, "','");
	double start = inner_float(p);
	parse_expect(p, TOK_COMMA);
	double end = inner_float(p);
	double step = 1;
	if (parse_accept(p, TOK_COMMA)) {
		struct srcpos spos = parse_peek(p)->pos;
		step = inner_float(p);
		if (step == 0)
			parse_error_at(p, spos, "a #for step of 0 would never end");
	}
	parse_expect(p, TOK_RPAREN);
	declare_float(p, id.str, start);
	if (!for_continues(start, end, step)) {
		skip_block(p, STOP_END, 0, at, "#for");
		return;
	}
	struct cond *c = push_cond(p, COND_FOR, at);
	c->var = id.str;
	c->end = end;
	c->step = step;
	c->loop = top(p)->pos;
}

static void dir_end(struct parser *p, struct srcpos at)
{
	struct cond *c = top_cond(p);
	if (!c)
		parse_error_at(p, at, "#end without an open #if, #ifdef, #ifndef, #switch, #while, #for or #macro");
	switch (c->kind) {
	case COND_IF:
	case COND_SWITCH:
		p->nconds--;
		break;
	case COND_WHILE:
		/* Back to the '#' of the #while, which runs again. */
		top(p)->pos = c->loop;
		p->nconds--;
		break;
	case COND_FOR: {
		struct value *v = parse_lookup(p, c->var);
		if (!v || v->kind != VAL_FLOAT)
			parse_error_at(p, at, "the #for loop variable '%s' is no longer a float", c->var);
		double next = v->v[0] + c->step;
		v->v[0] = next;
		if (for_continues(next, c->end, c->step))
			top(p)->pos = c->loop;
		else
			p->nconds--;
		break;
	}
	}
}

/* ---- #macro and macro calls ---- */

static void free_macro_value(void *v)
{
	val_clear(v);
	free(v);
}

/* #macro IDENT ( [IDENT {, IDENT}] ) body #end */
static void dir_macro(struct parser *p, struct srcpos at)
{
	struct token name = parse_raw(p);
	if (name.kind != TOK_IDENT)
		raw_expected(p, &name, name.kind == TOK_KEYWORD ? "a macro name that is not a reserved word" : "a macro name");
	raw_expect(p, TOK_LPAREN, "'(' after the macro's name");
	struct macro *m = calloc(1, sizeof *m);
	if (!m) abort();
	m->refs = 1;
	m->name = name.str;
	m->pos = at;
	struct value *holder = malloc(sizeof *holder);
	if (!holder) abort();
	holder->kind = VAL_MACRO;
	holder->mac = m;
	int slot = parse_own(p, holder, free_macro_value);
	int cap = 0;
	struct token t = parse_raw(p);
	while (t.kind != TOK_RPAREN) {
		if (t.kind != TOK_IDENT)
			raw_expected(p, &t, "a parameter name or ')'");
		for (int i = 0; i < m->nparams; i++)
			if (m->params[i] == t.str)
				parse_error_at(p, t.pos, "macro %s has two parameters named '%s'", m->name, t.str);
		if (m->nparams == cap) {
			cap = cap ? cap * 2 : 4;
			m->params = realloc(m->params, (size_t)cap * sizeof *m->params);
			if (!m->params) abort();
		}
		m->params[m->nparams++] = t.str;
		/* As in POV-Ray the commas may be left out, and one may
		 * follow the last parameter. */
		t = parse_raw(p);
		if (t.kind == TOK_COMMA)
			t = parse_raw(p);
	}
	struct frame *f = top(p);
	m->file = f->file;
	m->body = f->pos;
	skip_block(p, STOP_END, 0, at, "#macro");
	m->end = f->pos - 2; /* the '#' of the #end */
	parse_release(p, slot);
	free(holder);
	struct value v = {.kind = VAL_MACRO, .pos = at, .mac = m};
	sym_set(p->globals, name.str, v);
}

enum { MAX_MACRO_ARGS = 256 };

/* If the raw tokens at f->pos are IDENT or IDENT[...]... followed by ','
 * or ')', the index of that ',' or ')'; else 0. */
static size_t byref_end(const struct frame *f)
{
	size_t i = f->pos;
	if (i >= f->end || f->toks[i].kind != TOK_IDENT)
		return 0;
	i++;
	while (i < f->end && f->toks[i].kind == TOK_LBRACKET) {
		int depth = 0;
		for (; i < f->end; i++) {
			if (f->toks[i].kind == TOK_LBRACKET)
				depth++;
			else if (f->toks[i].kind == TOK_RBRACKET && --depth == 0)
				break;
		}
		if (i >= f->end)
			return 0;
		i++;
	}
	if (i < f->end && (f->toks[i].kind == TOK_COMMA || f->toks[i].kind == TOK_RPAREN))
		return i;
	return 0;
}

size_t parse_array_index(struct parser *p, const struct array *a, const char *name, struct srcpos at)
{
	int ndims = a->ndims, dims[ARRAY_MAX_DIMS];
	memcpy(dims, a->dims, sizeof dims);
	size_t idx = 0;
	for (int d = 0; d < ndims; d++) {
		if (!parse_is(p, TOK_LBRACKET))
			parse_error_at(p, at, "array '%s' has %d dimensions: give an index for each", name, ndims);
		parse_advance(p);
		bool rel = parse_set_rel(p, true); /* inside brackets everything binds */
		struct value e = parse_expression(p);
		p->rel_ok = rel;
		parse_need_float(p, &e, "an array index");
		double i = trunc(e.v[0]);
		if (i < 0 || i >= dims[d])
			parse_error_at(p, e.pos, "index %g is out of range for dimension %d of array '%s' (size %d)",
			               i, d + 1, name, dims[d]);
		parse_expect(p, TOK_RBRACKET);
		idx = idx * (size_t)dims[d] + (size_t)i;
	}
	return idx;
}

/* Drop a reference to a macro taken by parse_call_macro (for parse_own). */
static void macro_unref(void *m)
{
	struct value v = {.kind = VAL_MACRO, .mac = m};
	val_clear(&v);
}

void parse_call_macro(struct parser *p, const struct token *name, struct macro *m)
{
	struct token lp = parse_raw(p);
	if (lp.kind != TOK_LPAREN)
		raw_expected(p, &lp, "'(' after the macro name");
	/* The arguments may run directives, and a #macro among them may
	 * replace this very macro: hold it until its frame is set up. */
	m->refs++;
	int mslot = parse_own(p, m, macro_unref);
	struct symtab *locals = p->spare_locals ? p->spare_locals : sym_new();
	p->spare_locals = NULL;
	sym_track(locals, &p->bindgen, &p->lookgen);
	int slot = parse_own(p, locals, (void (*)(void *))sym_free);
	int n = 0;
	struct frame *f = top(p);
	if (f->pos < f->end && f->toks[f->pos].kind == TOK_RPAREN) {
		f->pos++;
	} else {
		for (;;) {
			f = top(p);
			const struct token *a = &f->toks[f->pos];
			struct value v;
			memset(&v, 0, sizeof v);
			/* A lone identifier, or an array element A[i], is passed by
			 * reference: assigning the parameter inside the macro
			 * changes the caller's variable. */
			bool byref = false;
			size_t after = byref_end(f);
			if (after) {
				const char *target = a->str;
				struct value *b = parse_lookup(p, target);
				if (b && b->kind != VAL_MACRO && (after == f->pos + 1 || b->kind == VAL_ARRAY)) {
					struct srcpos apos = a->pos;
					f->pos++;
					struct symtab *t = parse_alias_target(p, &target);
					size_t idx = ALIAS_WHOLE;
					if (after != f->pos)
						idx = parse_array_index(p, b->arr, target, apos);
					v.kind = VAL_ALIAS;
					v.alias.table = t;
					v.alias.name = target;
					v.alias.index = idx;
					v.pos = apos;
					byref = true;
				}
			}
			if (!byref) {
				/* Inside the call's parentheses everything binds. A
				 * numeric argument read before is run from its
				 * compiled form (exprcache.h) without parse_rvalue's
				 * tests for scene items: only an expression was ever
				 * compiled at its first token. */
				bool rel = parse_set_rel(p, true);
				struct exprcache_ticket tk;
				if (!exprcache_try(p, &v, &tk))
					v = parse_rvalue(p);
				p->rel_ok = rel;
			}
			if (n < m->nparams)
				sym_set(locals, m->params[n], v);
			else
				val_clear(&v);
			n++;
			if (n > MAX_MACRO_ARGS)
				parse_error_at(p, name->pos, "more than %d arguments in a macro call", MAX_MACRO_ARGS);
			/* POV-Ray lets the commas be left out, and one follow
			 * the last argument. */
			bool comma = parse_accept(p, TOK_COMMA);
			/* Look at the next token raw: reading it would take a lone
			 * identifier that the next argument passes by reference. */
			f = top(p);
			if (!p->have_cur && f->pos < f->end && f->toks[f->pos].kind == TOK_RPAREN) {
				f->pos++;
				break;
			}
			if (comma || (!p->have_cur && f->pos < f->end && f->toks[f->pos].kind != TOK_HASH))
				continue;
			if (parse_accept(p, TOK_RPAREN))
				break;
			if (!parse_is(p, TOK_EOF))
				continue;
			parse_expected(p, "',' or ')' after a macro argument");
		}
	}
	const struct value *now = parse_lookup(p, m->name);
	if (!now || now->kind != VAL_MACRO || now->mac != m)
		parse_error_at(p, name->pos, "macro %s was redefined or undefined while the arguments of its call "
		               "were read", m->name);
	if (n != m->nparams)
		parse_error_at(p, name->pos, "macro %s takes %d argument%s, but %d %s given", m->name, m->nparams,
		               m->nparams == 1 ? "" : "s", n, n == 1 ? "was" : "were");
	parse_step(p, name->pos, false);
	const struct srcfile *sf = src_file(p->sm, m->file);
	parse_release(p, slot);
	struct frame *mf;
	{
		/* push_frame's checks, then fill in the body. */
		size_t macros = 0;
		for (int i = 0; i < p->nframes; i++)
			macros += p->frames[i].kind == FRAME_MACRO;
		if (macros >= p->lim.macro_depth || p->nframes == p->capframes) {
			sym_free(locals);
			parse_error_at(p, name->pos, "macro calls nested too deeply (more than %zu levels): is %s recursing "
			               "without end? (lucent --limit macro-depth=N raises the limit)", p->lim.macro_depth,
			               m->name);
		}
		mf = &p->frames[p->nframes++];
		p->events++;
		p->bindgen++;
		memset(mf, 0, sizeof *mf);
	}
	mf->kind = FRAME_MACRO;
	mf->file = m->file;
	mf->toks = sf->toks;
	mf->pos = m->body;
	mf->end = m->end;
	mf->from = name->pos;
	mf->macro = m->name;
	mf->locals = locals;
	mf->nconds = p->nconds;
	/* The parameters now hide any other bindings of their names. */
	sym_touch(locals);
	parse_release(p, mslot);
	macro_unref(m); /* its binding still holds it */
}

/* ---- #declare, #local, #undef ---- */

/* Run the directives waiting in the lookahead that close the blocks an
 * operand was inside (#else, #end ... of `#declare A = #if (c) 1 #else 2
 * #end;`). Returns when the lookahead is something else. */
static void run_closing_directives(struct parser *p)
{
	for (;;) {
		const struct token *t = parse_peek_cont(p);
		if (t->kind != TOK_HASH)
			return;
		struct frame *f = top(p);
		const struct token *k = f->pos + 1 < f->end ? &f->toks[f->pos + 1] : NULL;
		if (!k || k->kind != TOK_KEYWORD)
			return;
		switch (k->kw) {
		case KW_ELSE: case KW_ELSEIF: case KW_END: case KW_BREAK: case KW_CASE: case KW_RANGE:
			break;
		default:
			return;
		}
		p->have_cur = false;
		f->pos++; /* the '#' */
		parse_directive(p, f->pos - 1);
	}
}

/* The semicolon after a declaration: required after floats, vectors and
 * colors since 3.7. */
static void end_declaration(struct parser *p, bool numeric, const char *what)
{
	run_closing_directives(p);
	const struct token *t = parse_peek_cont(p);
	if (t->kind == TOK_SEMI) {
		parse_advance(p);
		return;
	}
	switch (t->kind) {
	case TOK_LT: case TOK_GT: case TOK_LE: case TOK_GE: case TOK_EQ: case TOK_NE:
	case TOK_AMP: case TOK_BAR: case TOK_QUESTION:
		parse_error_at(p, t->pos, "'%s' outside parentheses: POV-Ray compares and tests only inside "
		               "them, as in (A < B)", lex_kind_name((enum tok_kind)t->kind));
	default:
		break;
	}
	if (numeric && p->version >= 3.5)
		parse_error_at(p, p->prev.pos, "expected ';' after the value of '%s': POV-Ray needs it for floats, vectors and colors", what);
}

/* IDENT '[' INT ']' ... '=' value : assign one element of an array. */
static void declare_element(struct parser *p, const char *name, bool local, struct srcpos at)
{
	const struct value *av = parse_lookup(p, name);
	if (!av)
		parse_error_at(p, at, "'%s' is not declared, so it has no elements to assign", name);
	if (av->kind != VAL_ARRAY)
		parse_error_at(p, at, "'%s' is a %s, not an array", name, val_kind_name(av->kind));
	size_t idx = parse_array_index(p, av->arr, name, at);
	parse_expect(p, TOK_EQ);
	int home = p->nframes - 1;
	struct value v = parse_rvalue(p);
	bool numeric = val_is_numeric(&v);
	parse_leave_finished(p, home);
	/* Find the array again: reading the value may have run code. An
	 * element is assigned where the array is, with #local too. */
	(void)local;
	struct value *slot = parse_lookup(p, name);
	if (!slot) {
		val_clear(&v);
		parse_error_at(p, at, "array '%s' was undefined while its element was being assigned", name);
	}
	if (slot->kind != VAL_ARRAY || idx >= slot->arr->count) {
		val_clear(&v);
		parse_error_at(p, at, "array '%s' was changed while its element was being assigned", name);
	}
	struct array *w = array_unshare(slot);
	val_clear(&w->elems[idx]);
	w->elems[idx] = v;
	end_declaration(p, numeric, name);
}

/* #declare [deprecated [once] [STRING]] IDENT ['[' INT ']'...] = value [;]
 * and the same with #local. */
static void dir_declare(struct parser *p, bool local)
{
	struct token id = parse_raw(p);
	const char *deprecated = NULL;
	bool once = false;
	if (id.kind == TOK_KEYWORD && id.kw == KW_DEPRECATED) {
		deprecated = "";
		id = parse_raw(p);
		if (id.kind == TOK_KEYWORD && id.kw == KW_ONCE) {
			once = true;
			id = parse_raw(p);
		}
		if (id.kind == TOK_STRING) {
			deprecated = id.str;
			id = parse_raw(p);
		}
	}
	if (id.kind == TOK_KEYWORD)
		parse_error_at(p, id.pos, "'%s' is a reserved word and cannot be declared", kw_names[id.kw]);
	if (id.kind != TOK_IDENT)
		raw_expected(p, &id, "an identifier to declare");
	/* The common case, IDENT '=' float-expression ';', from the
	 * expression's compiled form when it has one (exprcache.h). */
	struct frame *f = top(p);
	if (!deprecated && !p->have_cur && f->pos + 1 < f->end && f->toks[f->pos].kind == TOK_EQ) {
		f->pos++;
		double x;
		struct exprcache_ticket tk;
		const struct token *site = &f->toks[f->pos - 2]; /* the identifier, before the '=' */
		if (exprcache_try_float(p, &x, &tk)) {
			/* Written in place, as exprcache_try does. */
			struct value *slot = parse_declare_slot(p, site, local);
			val_clear(slot);
			memset(slot, 0, sizeof *slot);
			slot->kind = VAL_FLOAT;
			slot->n = 1;
			slot->pos = id.pos;
			slot->v[0] = x;
			f = top(p);
			if (f->pos < f->end && f->toks[f->pos].kind == TOK_SEMI) {
				f->pos++;
				p->prev = f->toks[f->pos - 1];
			} else {
				end_declaration(p, true, id.str);
			}
			return;
		}
		f->pos--; /* the ordinary way reads the '=' again */
	}
	if (parse_is(p, TOK_LBRACKET)) {
		declare_element(p, id.str, local, id.pos);
		return;
	}
	parse_expect(p, TOK_EQ);
	int home = p->nframes - 1;
	struct value v = parse_rvalue(p);
	v.pos = id.pos;
	v.deprecated = deprecated;
	v.deprecated_once = once;
	bool numeric = val_is_numeric(&v);
	/* Bind in the frame of the #declare, not in a macro the value called. */
	parse_leave_finished(p, home);
	parse_assign(p, id.str, local, v);
	end_declaration(p, numeric, id.str);
}

/* #undef IDENT: removes the innermost binding. */
static void dir_undef(struct parser *p)
{
	struct token id = parse_raw(p);
	if (id.kind != TOK_IDENT)
		raw_expected(p, &id, "an identifier after #undef");
	if (!parse_unbind(p, id.str))
		parse_warning_at(p, id.pos, "#undef of '%s', which is not declared", id.str);
}

/* ---- files and messages ---- */

static bool readable(const char *path) { return access(path, R_OK) == 0; }

/* Find an #include file: the including file's folder, the current folder,
 * each +L path, then lucent's stdlib. Returns a malloc'd path or NULL. */
static char *find_include(struct parser *p, const char *name, uint32_t from_file)
{
	char buf[PATH_MAX * 2];
	if (name[0] == '/')
		return readable(name) ? strdup(name) : NULL;
	const struct srcfile *sf = src_file(p->sm, from_file);
	if (sf) {
		const char *slash = strrchr(sf->path, '/');
		if (slash) {
			snprintf(buf, sizeof buf, "%.*s/%s", (int)(slash - sf->path), sf->path, name);
			if (readable(buf))
				return strdup(buf);
		}
	}
	if (readable(name))
		return strdup(name);
	for (size_t i = 0; i < p->o->nlib_paths; i++) {
		snprintf(buf, sizeof buf, "%s/%s", p->o->lib_paths[i], name);
		if (readable(buf))
			return strdup(buf);
	}
	if (p->o->stdlib_dir) {
		snprintf(buf, sizeof buf, "%s/%s", p->o->stdlib_dir, name);
		if (readable(buf))
			return strdup(buf);
	}
	return NULL;
}

char *parse_find_file(struct parser *p, const char *name, uint32_t from_file)
{
	char *path = find_include(p, name, from_file);
	if (path) {
		int slot = parse_own(p, path, free);
		parse_check_access(p, path, name, false, "an image map", p->prev.pos);
		parse_release(p, slot);
	}
	return path;
}

/* #include STRING */
static void dir_include(struct parser *p, struct srcpos at)
{
	/* parse_string reads nothing past the string, so the file is entered
	 * before any later token of the including file. */
	const char *name = parse_string(p);
	char *path = find_include(p, name, at.file);
	if (!path)
		parse_error_at(p, at, "cannot find include file \"%s\" (searched the including file's folder, the current folder, +L paths and the stdlib)", name);
	int pslot = parse_own(p, path, free);
	parse_check_access(p, path, name, false, "#include", at);
	parse_release(p, pslot);
	/* A file is read once, unless the scene has written some file since
	 * (it may have been this one: Parse_String of strings.inc). */
	uint32_t file = src_find(p->sm, path);
	if (file && src_file(p->sm, file)->writes != p->writes)
		file = 0;
	if (!file) {
		file = src_load(p->sm, path);
		if (file)
			p->sm->files[file]->writes = p->writes;
	}
	int err = errno;
	free(path);
	if (!file)
		parse_error_at(p, at, "cannot read include file \"%s\": %s", name, strerror(err));
	parse_push_file(p, file, at);
}

/* #debug / #warning / #error STRING */
static void dir_message(struct parser *p, enum kw which, struct srcpos at)
{
	const char *str = parse_string(p);
	char *text = malloc(strlen(str) + 1);
	if (!text) abort();
	ustr_to_ascii(str, text);
	int slot = parse_own(p, text, free);
	if (which == KW_DEBUG) {
		parse_debug_write(p, text);
	} else if (which == KW_WARNING) {
		parse_warning_at(p, at, "%s", text);
	} else {
		parse_error_at(p, at, "#error: %s", text);
	}
	parse_release(p, slot);
	free(text);
}

/* A character at which POV-Ray's #debug stream may break a line: a space,
 * tab, vertical tab or form feed (measured; '\n' and '\r' end the line). */
static bool debug_blank(char c)
{
	return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

/* The last blank among text[lo .. hi - 1], or -1. */
static int debug_last_blank(const char *text, int lo, int hi)
{
	for (int i = hi - 1; i >= lo; i--)
		if (debug_blank(text[i]))
			return i;
	return -1;
}

/* Write the n characters of text as lines of at most 80 columns, each
 * ended by a newline. A longer line breaks before its last blank in
 * columns 62 to 81, which begins the next line, or else after the 80th
 * character. */
static void debug_put(FILE *out, const char *text, int n)
{
	enum { WIDTH = 80, LOOK = 20 };
	while (n > WIDTH) {
		int cut = debug_last_blank(text, WIDTH + 1 - LOOK, WIDTH + 1);
		if (cut < 0)
			cut = WIDTH;
		fwrite(text, 1, (size_t)cut, out);
		fputc('\n', out);
		text += cut;
		n -= cut;
	}
	fwrite(text, 1, (size_t)n, out);
	fputc('\n', out);
}

/* POV-Ray's #debug stream, measured by running POV-Ray 3.7 on thousands
 * of generated messages (tests/lang/debug-wrap-*): text goes through a
 * buffer of 160 characters, which is written, wrapped by debug_put, when
 * a newline or '\r' comes and when a character arrives that does not fit:
 *  - a message longer than 200 characters is cut to its first 156 and
 *    "..." (its newline, if it had one, is lost with the rest);
 *  - when the 161st character arrives, the buffer and that character are
 *    written up to their last blank if it is among their last 40
 *    characters, and that blank and what follows stay in the buffer;
 *    otherwise the 160 are written and the new character stays;
 *  - what is in the buffer when the stream ends is never written.
 * Each write ends its last line, so a buffer always begins a line. This
 * gives POV-Ray's output byte for byte on 2,300 random messages mixing
 * long words, runs of blanks, newlines and many #debug calls per line. */
void parse_debug_write(struct parser *p, const char *text)
{
	FILE *out = p->o->debug_out ? p->o->debug_out : stderr;
	enum { SIZE = (int)sizeof p->debug_buf - 1, KEEP = 40, LONG = 200, CUT = 156 };
	size_t n = strlen(text);
	bool cut = n > LONG; /* (measured: tests/lang/debug-wrap-long) */
	if (cut)
		n = CUT;
	for (size_t k = 0; k < n + (cut ? 3 : 0); k++) {
		char c = k < n ? text[k] : '.';
		if (c == '\n' || c == '\r') {
			debug_put(out, p->debug_buf, p->debug_len);
			p->debug_len = 0;
			continue;
		}
		p->debug_buf[p->debug_len++] = c;
		if (p->debug_len > SIZE) {
			int at = debug_last_blank(p->debug_buf, p->debug_len - KEEP, p->debug_len);
			if (at < 0)
				at = SIZE;
			debug_put(out, p->debug_buf, at);
			p->debug_len -= at;
			memmove(p->debug_buf, p->debug_buf + at, (size_t)p->debug_len);
		}
	}
	fflush(out);
}

void parse_debug_flush(struct parser *p)
{
	FILE *out = p->o->debug_out ? p->o->debug_out : stderr;
	p->debug_len = 0;
	fflush(out);
}

/* #version FLOAT ; */
static void dir_version(struct parser *p)
{
	double v = parse_float(p);
	p->version = v;
	p->scene->version = v;
	p->scene->version_set = true;
	if (parse_peek_cont(p)->kind == TOK_SEMI)
		parse_advance(p);
}

/* ---- dispatch ---- */

void parse_directive(struct parser *p, size_t hash)
{
	struct srcpos at = top(p)->toks[hash].pos;
	p->events++;
	struct token kwt = parse_raw(p);
	if (kwt.kind != TOK_KEYWORD) {
		char buf[128];
		parse_error_at(p, kwt.pos, "expected a directive name after '#', found %s", lex_describe(&kwt, buf, sizeof buf));
	}
	parse_step(p, at, kwt.kw == KW_WHILE);
	if (++p->directive_depth > MAX_DIRECTIVE_DEPTH)
		parse_error_at(p, at, "directives nested inside each other too deeply (more than %d)", MAX_DIRECTIVE_DEPTH);
	bool outer_defer = p->defer;
	p->defer = true;
	/* #declare first: loops are mostly assignments. */
	if (kwt.kw == KW_DECLARE)
		dir_declare(p, false);
	else switch (kwt.kw) {
	case KW_DECLARE: dir_declare(p, false); break;
	case KW_LOCAL: dir_declare(p, true); break;
	case KW_UNDEF: dir_undef(p); break;
	case KW_INCLUDE: dir_include(p, at); break;
	case KW_DEBUG:
	case KW_WARNING:
	case KW_ERROR: dir_message(p, (enum kw)kwt.kw, at); break;
	case KW_VERSION: dir_version(p); break;
	case KW_IF: dir_if(p, at); break;
	case KW_IFDEF: dir_ifdef(p, at, true); break;
	case KW_IFNDEF: dir_ifdef(p, at, false); break;
	case KW_ELSE:
	case KW_ELSEIF: dir_else(p, at, (enum kw)kwt.kw); break;
	case KW_SWITCH: dir_switch(p, at); break;
	case KW_CASE:
	case KW_RANGE: dir_case(p, at, (enum kw)kwt.kw); break;
	case KW_BREAK: dir_break(p, at); break;
	case KW_WHILE: dir_while(p, at, hash); break;
	case KW_FOR: dir_for(p, at); break;
	case KW_END: dir_end(p, at); break;
	case KW_MACRO: dir_macro(p, at); break;
	case KW_FOPEN: parse_fopen(p, at); break;
	case KW_FCLOSE: parse_fclose(p); break;
	case KW_READ: parse_read(p, at); break;
	case KW_WRITE: parse_write(p); break;
	case KW_DEFAULT: parse_default(p); break;
	default:
		parse_error_at(p, kwt.pos, "unknown directive '#%s'", kw_names[kwt.kw]);
	}
	p->defer = outer_defer;
	p->directive_depth--;
	/* A '#' that waited behind this directive's operands runs now, unless
	 * an enclosing directive is still reading its own. */
	if (!outer_defer && p->have_cur && p->cur.kind == TOK_HASH)
		p->have_cur = false;
}

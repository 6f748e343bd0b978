/* parse.c: the parser's core: the error boundary, ownership of what a
 * failed parse leaves behind, the token stream (frames of files and macro
 * bodies, with directives and macro calls run in it), and symbol scopes.
 * The directives themselves are in directive.c. */
#include "lang/parser.h"

#include "lang/intern.h"

#include <errno.h>
#include <limits.h>
#include <stddef.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* ---- errors ---- */

void parse_error_at(struct parser *p, struct srcpos pos, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vreport(p->d, DIAG_ERROR, pos, fmt, ap);
	va_end(ap);
	longjmp(*p->boundary, 1);
}

void parse_error(struct parser *p, const char *fmt, ...)
{
	va_list ap;
	struct srcpos pos = parse_peek(p)->pos;
	va_start(ap, fmt);
	diag_vreport(p->d, DIAG_ERROR, pos, fmt, ap);
	va_end(ap);
	longjmp(*p->boundary, 1);
}

void parse_limits_default(struct parse_limits *l)
{
	*l = (struct parse_limits){
		.macro_depth = 1000, .include_depth = 100, .expr_depth = 256, .csg_depth = 1000,
		.array_size = 100000000, .string_length = 1u << 28, .mesh_size = 100000000,
	};
}

bool parse_limits_set(struct parse_limits *l, const char *name, size_t value)
{
	static const struct { const char *name; size_t off; } fields[] = {
		{"macro-depth", offsetof(struct parse_limits, macro_depth)},
		{"include-depth", offsetof(struct parse_limits, include_depth)},
		{"expr-depth", offsetof(struct parse_limits, expr_depth)},
		{"csg-depth", offsetof(struct parse_limits, csg_depth)},
		{"array-size", offsetof(struct parse_limits, array_size)},
		{"string-length", offsetof(struct parse_limits, string_length)},
		{"mesh-size", offsetof(struct parse_limits, mesh_size)},
	};
	for (size_t i = 0; i < sizeof fields / sizeof fields[0]; i++)
		if (strcmp(name, fields[i].name) == 0) {
			*(size_t *)((char *)l + fields[i].off) = value;
			return true;
		}
	return false;
}

bool parse_memory_ok(size_t n, size_t size)
{
	long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
	if (pages <= 0 || page <= 0)
		return true;
	double have = (double)pages * (double)page;
	return (double)n * (double)size <= have;
}

void parse_step(struct parser *p, struct srcpos pos, bool loop_head)
{
	p->steps++;
	if (p->o->stop && *p->o->stop) {
		p->interrupted = true;
		/* The innermost loop: the #while at pos itself (a loop's #end
		 * closes it before its #while runs again), else the innermost
		 * one open. */
		struct srcpos lpos = pos;
		const char *kind = "while";
		bool found = loop_head;
		for (int i = p->nconds - 1; i >= 0 && !found; i--)
			if (p->conds[i].kind == COND_WHILE || p->conds[i].kind == COND_FOR) {
				lpos = p->conds[i].pos;
				kind = p->conds[i].kind == COND_WHILE ? "while" : "for";
				found = true;
			}
		const struct srcfile *lf = found ? src_file(p->sm, lpos.file) : NULL;
		if (lf)
			diag_report(p->d, DIAG_ERROR, pos, "interrupted while parsing, in the #%s loop at %s:%u", kind,
			            lf->path, lpos.line);
		else
			diag_report(p->d, DIAG_ERROR, pos, "interrupted while parsing");
		longjmp(*p->boundary, 1);
	}
	if (p->o->max_steps && p->steps > p->o->max_steps)
		parse_error_at(p, pos, "the scene ran more than %lu directives and macro calls (the limit set for this run)",
		               p->o->max_steps);
}

void parse_expected(struct parser *p, const char *what)
{
	char buf[128];
	parse_error(p, "expected %s, found %s", what, lex_describe(parse_peek(p), buf, sizeof buf));
}

void parse_warning_at(struct parser *p, struct srcpos pos, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vreport(p->d, DIAG_WARNING, pos, fmt, ap);
	va_end(ap);
}

static bool same_entry(const struct frame *a, const struct frame *b)
{
	return a->kind == b->kind && a->macro == b->macro && a->from.file == b->from.file &&
	       a->from.line == b->from.line && a->from.col == b->from.col;
}

/* Prints the chain of includes and macro calls that led to the current
 * position, innermost first. A run of identical entries (recursion) is
 * printed once with its count. */
static void print_context(void *arg, FILE *out)
{
	struct parser *p = arg;
	for (int i = p->nframes - 1; i > 0; i--) {
		const struct frame *f = &p->frames[i];
		int repeats = 0;
		while (i - 1 > 0 && same_entry(f, &p->frames[i - 1])) {
			repeats++;
			i--;
		}
		const struct srcfile *sf = src_file(p->sm, f->from.file);
		if (!sf)
			continue;
		if (f->kind == FRAME_MACRO)
			fprintf(out, "  in macro %s called from %s:%u:%u", f->macro, sf->path, f->from.line, f->from.col);
		else
			fprintf(out, "  included from %s:%u:%u", sf->path, f->from.line, f->from.col);
		if (repeats)
			fprintf(out, " (and %d more times from there)", repeats);
		fputc('\n', out);
	}
}

/* ---- ownership ---- */

int parse_own(struct parser *p, void *ptr, void (*fn)(void *))
{
	if (p->nowned == MAX_OWNED)
		parse_error(p, "scene items nested too deeply (more than %d)", MAX_OWNED);
	p->owned[p->nowned].ptr = ptr;
	p->owned[p->nowned].free = fn;
	return p->nowned++;
}

void parse_release(struct parser *p, int slot)
{
	/* Slots are normally released last-in first-out; releasing an inner
	 * one first just leaves a hole until the ones above it go. */
	p->owned[slot].ptr = NULL;
	while (p->nowned > 0 && p->owned[p->nowned - 1].ptr == NULL)
		p->nowned--;
}

void parse_take(struct parser *p, struct value *v)
{
	if (v->owner > 0) {
		struct value *held = p->owned[v->owner - 1].ptr;
		parse_release(p, v->owner - 1);
		free(held);
		v->owner = 0;
	}
}

void parse_drop(struct parser *p, struct value *v)
{
	parse_take(p, v);
	val_clear(v);
}

/* ---- frames and the token stream ---- */

static void check_frame_conds(struct parser *p, int frame)
{
	if (p->nconds > 0 && p->conds[p->nconds - 1].frame == frame) {
		const struct cond *c = &p->conds[p->nconds - 1];
		static const char *const names[] = {"#if", "#switch", "#while", "#for"};
		parse_error_at(p, c->pos, "%s is never closed by #end%s", names[c->kind],
		               p->frames[frame].kind == FRAME_MACRO ? " inside its macro" : " in its file");
	}
}

static void pop_frame(struct parser *p)
{
	struct frame *f = &p->frames[p->nframes - 1];
	check_frame_conds(p, p->nframes - 1);
	p->events++;
	p->bindgen++;
	/* A macro's table is emptied and kept for the next call. */
	if (f->kind == FRAME_MACRO && f->locals && !p->spare_locals) {
		sym_clear(f->locals);
		p->spare_locals = f->locals;
	} else {
		sym_free(f->locals);
	}
	f->locals = NULL;
	p->nframes--;
}

static struct frame *push_frame(struct parser *p, struct srcpos from)
{
	if (p->nframes == p->capframes)
		parse_error_at(p, from, "includes and macro calls nested too deeply (more than %d levels; "
		               "lucent --limit macro-depth=N raises it)", p->capframes);
	struct frame *f = &p->frames[p->nframes++];
	p->events++;
	p->bindgen++;
	memset(f, 0, sizeof *f);
	f->from = from;
	f->nconds = p->nconds;
	return f;
}

void parse_push_file(struct parser *p, uint32_t file, struct srcpos from)
{
	int includes = 0;
	for (int i = 0; i < p->nframes; i++)
		includes += p->frames[i].kind == FRAME_FILE;
	if ((size_t)includes > p->lim.include_depth)
		parse_error_at(p, from, "includes nested too deeply (more than %zu levels; lucent --limit include-depth=N "
		               "raises it)", p->lim.include_depth);
	struct frame *f = push_frame(p, from);
	f->kind = FRAME_FILE;
	f->file = file;
	f->locals = p->nframes > 1 ? sym_new() : NULL;
	if (f->locals)
		sym_track(f->locals, &p->bindgen, &p->lookgen);
	/* Lex with the frame in place, so a lexical error shows the include
	 * chain that led to this file. */
	if (!lex_file(p->sm, file, p->d))
		longjmp(*p->boundary, 1);
	const struct srcfile *sf = src_file(p->sm, file);
	f->toks = sf->toks;
	f->pos = 0;
	f->end = sf->ntoks - 1; /* the TOK_EOF */
}

struct token parse_raw_next(struct parser *p)
{
	for (;;) {
		struct frame *f = &p->frames[p->nframes - 1];
		if (f->pos < f->end)
			return f->toks[f->pos++];
		if (p->nframes == 1) {
			check_frame_conds(p, 0);
			return f->toks[f->end]; /* TOK_EOF of the main file */
		}
		pop_frame(p);
	}
}

/* A '#' held as the lookahead is the sentinel of parse_peek_cont: the
 * directive is still in its frame, and runs when a token is really needed. */
static void drop_sentinel(struct parser *p)
{
	if (p->have_cur && p->cur.kind == TOK_HASH)
		p->have_cur = false;
}

/* Make the next token current, running directives and macro calls before
 * it. */
static void fetch(struct parser *p)
{
	while (!p->have_cur) {
		struct token t = parse_raw(p);
		if (t.kind == TOK_HASH) {
			struct frame *f = &p->frames[p->nframes - 1];
			parse_directive(p, f->pos - 1);
			/* A directive read inside another's operands (an object
			 * #declared through a macro whose body has #locals) may
			 * leave the '#' after it as the lookahead; fetch wants a
			 * real token, so that directive runs now. */
			drop_sentinel(p);
			continue;
		}
		if (t.kind == TOK_IDENT) {
			struct value *v = parse_lookup(p, t.str);
			if (v && v->kind == VAL_MACRO) {
				parse_call_macro(p, &t, v->mac);
				continue;
			}
		}
		p->cur = t;
		p->have_cur = true;
	}
}


const struct token *parse_peek_fetch(struct parser *p)
{
	drop_sentinel(p);
	if (!p->have_cur)
		fetch(p);
	return &p->cur;
}

const struct token *parse_peek_cont(struct parser *p)
{
	if (p->have_cur || !p->defer) {
		if (!p->have_cur)
			fetch(p);
		return &p->cur;
	}
	const struct frame *f = &p->frames[p->nframes - 1];
	if (f->pos < f->end) {
		/* The common case: look at the frame's next token in place. */
		if (f->toks[f->pos].kind == TOK_HASH) {
			p->cur = f->toks[f->pos];
			p->have_cur = true;
			return &p->cur;
		}
		fetch(p);
		return &p->cur;
	}
	struct token t = parse_raw(p);
	if (t.kind != TOK_EOF)
		p->frames[p->nframes - 1].pos--; /* put it back */
	if (t.kind == TOK_HASH) {
		p->cur = t;
		p->have_cur = true;
		return &p->cur;
	}
	fetch(p);
	return &p->cur;
}

const struct token *parse_peek_raw(struct parser *p)
{
	if (p->have_cur)
		return &p->cur;
	const struct frame *f = &p->frames[p->nframes - 1];
	return f->pos < f->end ? &f->toks[f->pos] : NULL;
}

void parse_expect_fail(struct parser *p, enum tok_kind k)
{
	char what[32];
	snprintf(what, sizeof what, "'%s'", lex_kind_name(k));
	parse_expected(p, what);
}

/* ---- symbols ---- */

/* The innermost binding of name, and the table holding it. */
static struct value *find_binding(struct parser *p, const char *name, struct symtab **where)
{
	for (int i = p->nframes - 1; i >= 0; i--)
		if (p->frames[i].locals) {
			struct value *v = sym_get(p->frames[i].locals, name);
			if (v) {
				*where = p->frames[i].locals;
				return v;
			}
		}
	*where = p->globals;
	return sym_get(p->globals, name);
}

/* Each frame adds at most one link to a chain of by-reference parameters:
 * a bound far past any frame limit only guards against a cycle. */
enum { ALIAS_MAX_HOPS = 1 << 24 };

/* The binding an alias names (an array element for A[i] passed by
 * reference); NULL if it no longer exists. With `write`, the array is
 * unshared first and a missing whole binding is created. */
static struct value *follow_alias(struct value *v, bool write)
{
	for (int hops = 0; v && v->kind == VAL_ALIAS && hops < ALIAS_MAX_HOPS; hops++) {
		struct alias a = v->alias;
		v = sym_get(a.table, a.name);
		if (!v && write && a.index == ALIAS_WHOLE) {
			sym_set(a.table, a.name, (struct value){.kind = VAL_NONE});
			v = sym_get(a.table, a.name);
		}
		if (v && a.index != ALIAS_WHOLE) {
			if (v->kind != VAL_ARRAY || a.index >= v->arr->count)
				return NULL;
			struct array *arr = write ? array_unshare(v) : v->arr;
			v = &arr->elems[a.index];
		}
	}
	return v;
}

struct value *parse_binding(struct parser *p, const char *name)
{
	struct symtab *t;
	return find_binding(p, name, &t);
}

struct value *parse_lookup(struct parser *p, const char *name)
{
	struct symtab *t;
	struct value *v = find_binding(p, name, &t);
	/* A by-reference parameter names its caller's binding; chains of them
	 * (a parameter passed on) are short, and end. */
	v = follow_alias(v, false);
	return v && v->kind != VAL_NONE ? v : NULL;
}

struct value *parse_assign_slot(struct parser *p, const char *name, bool local)
{
	struct symtab *t;
	struct value *v;
	if (local) {
		t = parse_local_table(p);
		v = sym_get(t, name);
	} else {
		v = find_binding(p, name, &t);
		if (!v)
			t = p->globals;
	}
	if (!v) {
		sym_set(t, name, (struct value){.kind = VAL_NONE});
		return sym_get(t, name);
	}
	/* Through a by-reference parameter, #declare and #local both write
	 * the caller's variable (POV-Ray's behaviour). */
	if (v->kind == VAL_ALIAS) {
		struct value *target = follow_alias(v, true);
		if (target)
			return target;
		sym_set(t, name, (struct value){.kind = VAL_NONE});
		return sym_get(t, name);
	}
	return v;
}

struct value *parse_declare_slot_find(struct parser *p, const struct token *site, bool local)
{
	struct decl_cache *c = &p->declcache[((uintptr_t)site / sizeof *site) & (DECL_CACHE - 1)];
	const char *name = site->str;
	struct symtab *t;
	struct value *v = local ? sym_get(t = parse_local_table(p), name) : find_binding(p, name, &t);
	if (v && v->kind == VAL_ALIAS)
		return parse_assign_slot(p, name, local); /* followed every time */
	if (!v) {
		if (!local)
			t = p->globals;
		sym_set(t, name, (struct value){.kind = VAL_NONE});
		v = sym_get(t, name);
	}
	c->site = site;
	c->slot = v;
	c->bucket = sym_gen_bucket(name);
	c->gen = local ? p->bindgen : p->lookgen.name[c->bucket];
	c->local = local;
	return v;
}

void parse_assign(struct parser *p, const char *name, bool local, struct value v)
{
	struct value *slot = parse_assign_slot(p, name, local);
	val_clear(slot);
	*slot = v;
}

struct symtab *parse_alias_target(struct parser *p, const char **name)
{
	struct symtab *t;
	struct value *v = find_binding(p, *name, &t);
	for (int hops = 0; v && v->kind == VAL_ALIAS && v->alias.index == ALIAS_WHOLE && hops < ALIAS_MAX_HOPS; hops++) {
		t = v->alias.table;
		*name = v->alias.name;
		v = sym_get(t, *name);
	}
	return t;
}

struct suggest {
	const char *name;
	size_t namelen;
	size_t limit; /* the largest distance that is suggested */
	const char *best;
	size_t best_dist;
};

/* Edit distance, capped: the suggestion only matters when it is at most
 * `limit`, so any larger distance is returned as limit + 1, found without
 * filling the table when the lengths alone differ by more (a scene with
 * thousands of names made the error path cost more than the parse: the
 * fuzzer's profile). */
static size_t edit_distance(const char *a, size_t n, const char *b, size_t m, size_t limit)
{
	enum { CAP = 64 };
	if (n >= CAP || m >= CAP)
		return CAP;
	if ((n > m ? n - m : m - n) > limit)
		return limit + 1;
	size_t row[CAP + 1];
	for (size_t j = 0; j <= m; j++)
		row[j] = j;
	for (size_t i = 1; i <= n; i++) {
		size_t diag = row[0];
		row[0] = i;
		size_t low = row[0];
		for (size_t j = 1; j <= m; j++) {
			size_t up = row[j];
			size_t cost = a[i - 1] == b[j - 1] ? 0 : (a[i - 1] | 32) == (b[j - 1] | 32) ? 0 : 1;
			size_t best = diag + cost;
			if (up + 1 < best) best = up + 1;
			if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
			row[j] = best;
			diag = up;
			if (best < low) low = best;
		}
		if (low > limit) /* every later row is at least this */
			return limit + 1;
	}
	return row[m] > limit ? limit + 1 : row[m];
}

static void consider(void *arg, const char *cand)
{
	struct suggest *s = arg;
	size_t d = edit_distance(s->name, s->namelen, cand, strlen(cand), s->limit);
	if (d < s->best_dist || (d == s->best_dist && s->best && strcmp(cand, s->best) < 0)) {
		s->best_dist = d;
		s->best = cand;
	}
}

int parse_int_of(double x)
{
	if (!(x > -2147483649.0 && x < 2147483648.0))
		return INT_MIN;
	return (int)x;
}

void parse_undefined(struct parser *p, const char *name)
{
	size_t len = strlen(name);
	size_t limit = len <= 3 ? 1 : len / 3;
	struct suggest s = {name, len, limit, NULL, (size_t)-1};
	for (int i = p->nframes - 1; i >= 0; i--)
		if (p->frames[i].locals)
			sym_each(p->frames[i].locals, consider, &s);
	sym_each(p->globals, consider, &s);
	const char *kw_best = NULL;
	size_t kw_dist = (size_t)-1;
	for (int k = 1; k < KW__COUNT; k++) {
		size_t d = edit_distance(name, s.namelen, kw_names[k], strlen(kw_names[k]), limit);
		if (d < kw_dist) {
			kw_dist = d;
			kw_best = kw_names[k];
		}
	}
	if (s.best && s.best_dist <= limit && s.best_dist <= kw_dist)
		parse_error(p, "undefined identifier '%s'; did you mean '%s'?", name, s.best);
	if (kw_best && kw_dist <= limit)
		parse_error(p, "undefined identifier '%s'; did you mean the keyword '%s'?", name, kw_best);
	parse_error(p, "undefined identifier '%s'", name);
}

bool parse_unbind(struct parser *p, const char *name)
{
	for (int i = p->nframes - 1; i >= 0; i--)
		if (p->frames[i].locals && sym_remove(p->frames[i].locals, name))
			return true;
	return sym_remove(p->globals, name);
}

struct symtab *parse_local_table(struct parser *p)
{
	for (int i = p->nframes - 1; i >= 0; i--)
		if (p->frames[i].locals)
			return p->frames[i].locals;
	return p->globals;
}

void parse_leave_finished(struct parser *p, int home)
{
	while (!p->have_cur && p->nframes - 1 > home && p->nframes > 1) {
		const struct frame *f = &p->frames[p->nframes - 1];
		if (f->pos < f->end)
			return;
		pop_frame(p);
	}
}

/* ---- entry ---- */

int parse_scene(struct srcmgr *sm, struct diag *d, const struct parse_opts *o, struct scene *s)
{
	jmp_buf jb;
	struct parser *p = calloc(1, sizeof *p);
	if (!p) abort();
	p->sm = sm;
	p->d = d;
	p->o = o;
	p->scene = s;
	p->names = sm->names;
	p->boundary = &jb;
	p->globals = sym_new();
	sym_track(p->globals, &p->bindgen, &p->lookgen);
	p->xcache = exprcache_new();
	p->version = 3.7;
	parse_limits_default(&p->lim);
	{
		/* The user's limits over the defaults. */
		const size_t *u = (const size_t *)&o->limits;
		size_t *l = (size_t *)&p->lim;
		for (size_t i = 0; i < sizeof p->lim / sizeof(size_t); i++)
			if (u[i])
				l[i] = u[i];
	}
	if (p->lim.expr_depth > INT_MAX / 2)
		p->lim.expr_depth = INT_MAX / 2;
	/* The main file, include_depth + 1 files (parse_push_file) and the
	 * macro calls. */
	size_t cap = p->lim.macro_depth + p->lim.include_depth + 2;
	p->capframes = cap > INT_MAX / 2 ? INT_MAX / 2 : (int)cap;
	p->frames = calloc((size_t)p->capframes, sizeof *p->frames);
	if (!p->frames) abort();
	d->context = print_context;
	d->context_arg = p;

	int rc = 0;
	if (setjmp(jb) == 0) {
		for (size_t i = 0; i < o->ndefines; i++) {
			struct value v = {.kind = VAL_FLOAT, .n = 1};
			v.v[0] = o->defines[i].value;
			sym_set(p->globals, intern_cstr(p->names, o->defines[i].name), v);
		}
		uint32_t file = src_load(sm, o->input);
		if (!file) {
			diag_report(d, DIAG_ERROR, (struct srcpos){0, 0, 0}, "cannot read scene file '%s': %s",
			            o->input, strerror(errno));
			longjmp(jb, 1);
		}
		parse_push_file(p, file, (struct srcpos){0, 0, 0});
		while (parse_peek(p)->kind != TOK_EOF)
			parse_statement(p);
	} else {
		rc = p->interrupted ? 2 : 1;
	}
	parse_debug_flush(p);
	/* Both paths: free what the parse still owns. */
	for (int i = p->nowned - 1; i >= 0; i--)
		if (p->owned[i].ptr)
			p->owned[i].free(p->owned[i].ptr);
	for (int i = p->nframes - 1; i >= 0; i--)
		sym_free(p->frames[i].locals);
	sym_free(p->globals);
	sym_free(p->spare_locals);
	free(p->rng);
	exprcache_free(p->xcache);
	parse_fonts_free(p);
	texture_unref(p->default_tex);
	d->context = NULL;
	d->context_arg = NULL;
	free(p->frames);
	free(p);
	return rc;
}

static void free_array_hold(void *a)
{
	struct value v = {.kind = VAL_ARRAY, .arr = a};
	val_clear(&v);
}

/* The next token of the current frame is '[' (looked at in place, so
 * that nothing is fetched: the lookahead stays free). */
static bool frame_next_is_lbracket(const struct parser *p)
{
	const struct frame *f = &p->frames[p->nframes - 1];
	return f->pos < f->end && f->toks[f->pos].kind == TOK_LBRACKET;
}

/* A[i]... where an item identifier is expected (object { A[i] },
 * texture { T[i] }, ...): reads the subscripts and returns the element,
 * leaving the identifier's token as the lookahead, so that the caller's
 * parse_advance passes over the whole reference. The array is held while
 * the indices are read; an index that redefines the array is an error. */
static const struct value *ident_element(struct parser *p, const struct value *v)
{
	struct token id = p->cur;
	parse_advance(p);
	struct array *held = v->arr;
	held->refs++;
	int slot = parse_own(p, held, free_array_hold);
	while (v->kind == VAL_ARRAY && frame_next_is_lbracket(p)) {
		size_t idx = parse_array_index(p, v->arr, id.str, id.pos);
		v = &v->arr->elems[idx];
		if (v->kind == VAL_NONE)
			parse_error_at(p, id.pos, "element of array '%s' used before it was given a value", id.str);
	}
	const struct value *now = parse_lookup(p, id.str);
	if (!now || now->kind != VAL_ARRAY || now->arr != held)
		parse_error_at(p, id.pos, "array '%s' was changed while its index was read", id.str);
	parse_release(p, slot);
	free_array_hold(held); /* the binding still holds it */
	p->cur = id;
	p->have_cur = true;
	p->cur_elem = v;
	p->cur_elem_at = id.pos;
	return v;
}

/* The lookahead is the identifier of an A[i]... already read: asked again
 * before it is consumed (texture { T[i] } looks for a texture, then for a
 * pigment), it stands for the same element. The identifier's own token,
 * read afresh (in a loop), is still followed by its '['. */
static bool at_read_element(const struct parser *p)
{
	return p->cur_elem && p->have_cur && p->cur.pos.file == p->cur_elem_at.file &&
	       p->cur.pos.line == p->cur_elem_at.line && p->cur.pos.col == p->cur_elem_at.col &&
	       !frame_next_is_lbracket(p);
}

const struct value *parse_ident_value(struct parser *p)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_IDENT)
		return NULL;
	if (at_read_element(p))
		return p->cur_elem;
	struct value *found = parse_lookup(p, t->str);
	if (!found)
		parse_undefined(p, t->str);
	parse_note_use(p, found, t->str, t->pos);
	const struct value *v = found;
	if (v->kind == VAL_ARRAY && frame_next_is_lbracket(p))
		v = ident_element(p, v);
	return v;
}

void parse_note_use(struct parser *p, struct value *v, const char *name, struct srcpos at)
{
	if (!v->deprecated)
		return;
	/* One token can be looked at twice: as an identifier of some kind,
	 * then as the start of an expression. No directive runs in between,
	 * so `events` tells that apart from a loop reading it again. */
	const struct srcpos *w = &p->deprecated_at;
	if (w->file == at.file && w->line == at.line && w->col == at.col && p->deprecated_ev == p->events)
		return;
	p->deprecated_at = at;
	p->deprecated_ev = p->events;
	if (*v->deprecated)
		parse_warning_at(p, at, "%s", v->deprecated);
	else
		parse_warning_at(p, at, "'%s' is deprecated", name);
	if (v->deprecated_once)
		v->deprecated = NULL;
}

void parse_wrong_kind(struct parser *p, const struct value *v, const char *want)
{
	parse_error(p, "'%s' is a %s, not %s", parse_peek(p)->str, val_kind_name(v->kind), want);
}

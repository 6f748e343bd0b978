/* parse.c: the parser's core: the error boundary, the token stream with
 * directives run in it, symbol scopes, and the directives themselves. */
#include "lang/parser.h"

#include "lang/intern.h"

#include <errno.h>
#include <limits.h>
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

/* Prints the chain of includes that led to the current position. */
static void print_context(void *arg, FILE *out)
{
	struct parser *p = arg;
	for (int i = p->nframes - 1; i > 0; i--) {
		const struct frame *f = &p->frames[i];
		const struct srcfile *sf = src_file(p->sm, f->from.file);
		if (sf)
			fprintf(out, "  included from %s:%u:%u\n", sf->path, f->from.line, f->from.col);
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
	/* Slots are released in LIFO order; releasing an inner one first is
	 * still correct, it just leaves a hole. */
	p->owned[slot].ptr = NULL;
	while (p->nowned > 0 && p->owned[p->nowned - 1].ptr == NULL)
		p->nowned--;
}

/* ---- token stream ---- */

static void directive(struct parser *p, struct srcpos at);

/* The next token from the innermost frame, leaving finished files. */
static struct token raw_next(struct parser *p)
{
	for (;;) {
		struct frame *f = &p->frames[p->nframes - 1];
		const struct token *t = &f->toks[f->pos];
		if (t->kind != TOK_EOF) {
			f->pos++;
			return *t;
		}
		if (p->nframes == 1)
			return *t;
		sym_free(f->locals);
		p->nframes--;
	}
}

/* Make the next token current, running any directives before it. */
static void fetch(struct parser *p)
{
	while (!p->have_cur) {
		struct token t = raw_next(p);
		if (t.kind == TOK_HASH) {
			directive(p, t.pos);
		} else {
			p->cur = t;
			p->have_cur = true;
		}
	}
}

const struct token *parse_peek(struct parser *p)
{
	if (!p->have_cur)
		fetch(p);
	return &p->cur;
}

void parse_advance(struct parser *p)
{
	if (!p->have_cur)
		fetch(p);
	p->prev = p->cur;
	p->have_cur = false;
}

bool parse_is(struct parser *p, enum tok_kind k) { return parse_peek(p)->kind == k; }
bool parse_is_kw(struct parser *p, enum kw k)
{
	const struct token *t = parse_peek(p);
	return t->kind == TOK_KEYWORD && t->kw == k;
}

bool parse_accept(struct parser *p, enum tok_kind k)
{
	if (parse_peek(p)->kind != k)
		return false;
	parse_advance(p);
	return true;
}

bool parse_accept_kw(struct parser *p, enum kw k)
{
	if (!parse_is_kw(p, k))
		return false;
	parse_advance(p);
	return true;
}

void parse_expect(struct parser *p, enum tok_kind k)
{
	if (parse_peek(p)->kind != k) {
		char what[32];
		snprintf(what, sizeof what, "'%s'", lex_kind_name(k));
		parse_expected(p, what);
	}
	parse_advance(p);
}

/* ---- symbols ---- */

struct value *parse_lookup(struct parser *p, const char *name)
{
	for (int i = p->nframes - 1; i >= 0; i--)
		if (p->frames[i].locals) {
			struct value *v = sym_get(p->frames[i].locals, name);
			if (v)
				return v;
		}
	return sym_get(p->globals, name);
}

/* ---- files ---- */

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

/* Push the tokens of `file` as a new frame. */
static void push_file(struct parser *p, uint32_t file, struct srcpos from)
{
	if (p->nframes == MAX_FRAMES)
		parse_error_at(p, from, "includes nested too deeply (more than %d levels)", MAX_FRAMES);
	if (!lex_file(p->sm, file, p->d))
		longjmp(*p->boundary, 1);
	const struct srcfile *sf = src_file(p->sm, file);
	struct frame *f = &p->frames[p->nframes++];
	f->kind = FRAME_FILE;
	f->file = file;
	f->toks = sf->toks;
	f->pos = 0;
	f->end = sf->ntoks;
	f->from = from;
	f->locals = p->nframes > 1 ? sym_new() : NULL;
}

/* ---- directives ---- */

/* #declare IDENT = value [;]  /  #local IDENT = value [;] */
static void dir_declare(struct parser *p, bool local)
{
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_KEYWORD)
		parse_error(p, "'%s' is a reserved word and cannot be declared", kw_names[t->kw]);
	if (t->kind != TOK_IDENT)
		parse_expected(p, "an identifier to declare");
	const char *name = t->str;
	struct srcpos npos = t->pos;
	parse_advance(p);
	parse_expect(p, TOK_EQ);
	struct value v;
	if (!parse_item_value(p, &v)) {
		if (!parse_starts_expression(p))
			parse_expected(p, "a value after '='");
		v = parse_expression(p);
	}
	v.pos = npos;
	/* Commit before looking at the next token, so that a directive right
	 * after this one already sees the new value. */
	struct symtab *tab = p->globals;
	if (local) {
		for (int i = p->nframes - 1; i >= 0; i--)
			if (p->frames[i].locals) {
				tab = p->frames[i].locals;
				break;
			}
	}
	sym_set(tab, name, v);
	parse_accept(p, TOK_SEMI);
}

/* #undef IDENT */
static void dir_undef(struct parser *p)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_IDENT)
		parse_expected(p, "an identifier after #undef");
	const char *name = t->str;
	struct srcpos pos = t->pos;
	parse_advance(p);
	bool found = false;
	for (int i = p->nframes - 1; i >= 0 && !found; i--)
		if (p->frames[i].locals)
			found = sym_remove(p->frames[i].locals, name);
	if (!found)
		found = sym_remove(p->globals, name);
	if (!found)
		parse_warning_at(p, pos, "#undef of '%s', which is not declared", name);
}

/* #include "file" */
static void dir_include(struct parser *p, struct srcpos at)
{
	/* parse_string reads nothing past the string, so the file is entered
	 * before any later token of the including file. */
	const char *name = parse_string(p);
	char *path = find_include(p, name, at.file);
	if (!path)
		parse_error_at(p, at, "cannot find include file \"%s\" (searched the including file's folder, the current folder, +L paths and the stdlib)", name);
	uint32_t file = src_find(p->sm, path);
	if (!file)
		file = src_load(p->sm, path);
	int err = errno;
	free(path);
	if (!file)
		parse_error_at(p, at, "cannot read include file \"%s\": %s", name, strerror(err));
	push_file(p, file, at);
}

/* #debug / #warning / #error "text" */
static void dir_message(struct parser *p, enum kw which, struct srcpos at)
{
	const char *text = parse_string(p);
	if (which == KW_DEBUG) {
		FILE *out = p->o->debug_out ? p->o->debug_out : stderr;
		fputs(text, out);
		fflush(out);
	} else if (which == KW_WARNING) {
		parse_warning_at(p, at, "%s", text);
	} else {
		parse_error_at(p, at, "#error: %s", text);
	}
}

/* #version FLOAT [;] */
static void dir_version(struct parser *p)
{
	double v = parse_float(p);
	p->version = v;
	p->scene->version = v;
	p->scene->version_set = true;
	parse_accept(p, TOK_SEMI);
}

/* Run the directive whose '#' was at `at`. Its tokens are all consumed on
 * return (the lookahead may already hold the token after it). */
static void directive(struct parser *p, struct srcpos at)
{
	struct token kwt = raw_next(p);
	if (kwt.kind != TOK_KEYWORD) {
		char buf[128];
		parse_error_at(p, kwt.pos, "expected a directive name after '#', found %s", lex_describe(&kwt, buf, sizeof buf));
	}
	switch (kwt.kw) {
	case KW_DECLARE: dir_declare(p, false); break;
	case KW_LOCAL: dir_declare(p, true); break;
	case KW_UNDEF: dir_undef(p); break;
	case KW_INCLUDE: dir_include(p, at); break;
	case KW_DEBUG:
	case KW_WARNING:
	case KW_ERROR: dir_message(p, (enum kw)kwt.kw, at); break;
	case KW_VERSION: dir_version(p); break;
	default:
		parse_error_at(p, kwt.pos, "unknown directive '#%s'", kw_names[kwt.kw]);
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
	p->version = 3.7;
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
		push_file(p, file, (struct srcpos){0, 0, 0});
		while (parse_peek(p)->kind != TOK_EOF)
			parse_statement(p);
	} else {
		rc = 1;
	}
	/* Both paths: free what the parse still owns. */
	for (int i = p->nowned - 1; i >= 0; i--)
		if (p->owned[i].ptr)
			p->owned[i].free(p->owned[i].ptr);
	for (int i = p->nframes - 1; i >= 0; i--)
		sym_free(p->frames[i].locals);
	sym_free(p->globals);
	texture_unref(p->default_tex);
	d->context = NULL;
	d->context_arg = NULL;
	free(p);
	return rc;
}

/* fileio.c: #fopen, #read, #write and #fclose. A file opened for reading
 * is lexed whole with the scene's own lexer, and #read takes its items
 * (numbers, vectors, strings) token by token; at the end of the file the
 * file's identifier becomes undefined, as in POV-Ray. */
#include "lang/parser.h"

#include "lang/intern.h"
#include "lang/ustr.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static void free_file_holder(void *h)
{
	val_clear(h);
	free(h);
}

/* The folder of the scene file, resolved ("." for standard input or a
 * bare name); malloc'd, or NULL if it cannot be resolved. */
static char *scene_folder(struct parser *p)
{
	const struct srcfile *main_file = src_file(p->sm, p->frames[0].file);
	const char *path = main_file ? main_file->path : ".";
	const char *slash = strrchr(path, '/');
	char dir[PATH_MAX];
	if (!slash)
		snprintf(dir, sizeof dir, ".");
	else if (slash == path)
		snprintf(dir, sizeof dir, "/");
	else
		snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
	return realpath(dir, NULL);
}

/* Is the resolved path inside the folder root (resolved too)? */
static bool inside(const char *path, const char *root)
{
	if (!root)
		return false;
	size_t n = strlen(root);
	if (n == 1 && root[0] == '/')
		return true;
	return strncmp(path, root, n) == 0 && (path[n] == '/' || path[n] == 0);
}

static bool inside_folder(const char *path, const char *folder)
{
	if (!folder)
		return false;
	char *root = realpath(folder, NULL);
	bool in = inside(path, root);
	free(root);
	return in;
}

/* path, resolved: symbolic links and '..' followed. A file that does not
 * exist yet (one to write) resolves through its folder. malloc'd, or NULL. */
static char *resolve(const char *path)
{
	char *r = realpath(path, NULL);
	if (r || errno != ENOENT)
		return r;
	const char *slash = strrchr(path, '/');
	char dir[PATH_MAX];
	snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - path) + (slash == path) : 1, slash ? path : ".");
	char *d = realpath(dir, NULL);
	if (!d)
		return NULL;
	const char *base = slash ? slash + 1 : path;
	if (strcmp(base, "..") == 0 || strcmp(base, ".") == 0 || !*base) {
		free(d);
		return NULL;
	}
	char *out = malloc(strlen(d) + strlen(base) + 2);
	if (!out) abort();
	sprintf(out, "%s%s%s", d, strcmp(d, "/") == 0 ? "" : "/", base);
	free(d);
	return out;
}

void parse_check_access(struct parser *p, const char *path, const char *name, bool writing, const char *what,
                        struct srcpos at)
{
	if (p->o->io_unrestricted)
		return;
	/* A path that does not resolve (a missing folder) is left to fail
	 * when it is opened: nothing can be read or written there. */
	char *r = resolve(path);
	bool ok = r == NULL;
	if (r) {
		char *scene = scene_folder(p);
		ok = inside(r, scene);
		free(scene);
		if (!ok && !writing) {
			for (size_t i = 0; !ok && i < p->o->nlib_paths; i++)
				ok = inside_folder(r, p->o->lib_paths[i]);
			if (!ok && p->o->stdlib_dir)
				ok = inside_folder(r, p->o->stdlib_dir);
		}
		free(r);
	}
	if (ok)
		return;
	if (writing)
		parse_error_at(p, at, "%s may not write \"%s\": scene files can only write in their own folder "
		               "(lucent --io-unrestricted lifts this)", what, name);
	parse_error_at(p, at, "%s may not read \"%s\": scene files can only read their own folder, "
	               "the +L library paths and the stdlib (lucent --io-unrestricted lifts this)", what, name);
}

/* The path of a file named in the scene: beside the scene file. */
static char *scene_relative(struct parser *p, const char *name)
{
	const struct srcfile *main_file = src_file(p->sm, p->frames[0].file);
	const char *slash = main_file ? strrchr(main_file->path, '/') : NULL;
	if (name[0] == '/' || !slash) {
		char *c = strdup(name);
		if (!c) abort();
		return c;
	}
	size_t dl = (size_t)(slash - main_file->path);
	char *c = malloc(dl + strlen(name) + 2);
	if (!c) abort();
	sprintf(c, "%.*s/%s", (int)dl, main_file->path, name);
	return c;
}

/* #fopen IDENT STRING (read | write | append) */
void parse_fopen(struct parser *p, struct srcpos at)
{
	struct token id = parse_raw(p);
	if (id.kind != TOK_IDENT)
		parse_error_at(p, id.pos, "expected a file identifier after #fopen");
	const char *name = parse_string(p);
	bool writing, append = false;
	if (parse_accept_kw(p, KW_READ))
		writing = false;
	else if (parse_accept_kw(p, KW_WRITE))
		writing = true;
	else if (parse_accept_kw(p, KW_APPEND))
		writing = append = true;
	else
		parse_expected(p, "read, write or append");
	char *path = scene_relative(p, name);
	int pslot = parse_own(p, path, free);
	parse_check_access(p, path, name, writing, "#fopen", at);
	parse_release(p, pslot);
	struct value *h = calloc(1, sizeof *h);
	if (!h) abort();
	h->kind = VAL_FILE;
	h->file = calloc(1, sizeof *h->file);
	if (!h->file) abort();
	h->file->refs = 1;
	h->file->name = name;
	h->file->writing = writing;
	int slot = parse_own(p, h, free_file_holder);
	if (writing) {
		p->writes++;
		h->file->fp = fopen(path, append ? "ab" : "wb");
		if (!h->file->fp) {
			int e = errno;
			free(path);
			parse_error_at(p, at, "cannot open \"%s\" for writing: %s", name, strerror(e));
		}
	} else {
		uint32_t file = src_load(p->sm, path);
		if (!file) {
			int e = errno;
			free(path);
			parse_error_at(p, at, "cannot open \"%s\" for reading: %s", name, strerror(e));
		}
		if (!lex_file(p->sm, file, p->d)) {
			free(path);
			longjmp(*p->boundary, 1);
		}
		const struct srcfile *sf = src_file(p->sm, file);
		h->file->toks = sf->toks; /* owned by the source manager */
		h->file->ntoks = sf->ntoks;
		h->file->borrowed_toks = true;
	}
	free(path);
	struct value v = *h;
	parse_release(p, slot);
	free(h);
	v.pos = id.pos;
	parse_assign(p, id.str, false, v);
}

/* #fclose IDENT */
void parse_fclose(struct parser *p)
{
	struct token id = parse_raw(p);
	if (id.kind != TOK_IDENT)
		parse_error_at(p, id.pos, "expected a file identifier after #fclose");
	struct value *v = parse_lookup(p, id.str);
	if (!v)
		return; /* closing a file that reached its end is allowed */
	if (v->kind != VAL_FILE)
		parse_error_at(p, id.pos, "'%s' is a %s, not a file", id.str, val_kind_name(v->kind));
	if (v->file->fp) {
		fclose(v->file->fp);
		v->file->fp = NULL;
	}
	parse_unbind(p, id.str);
}

static struct sdl_file *file_arg(struct parser *p, bool writing)
{
	const struct token *t = parse_peek(p);
	if (t->kind != TOK_IDENT)
		parse_expected(p, "a file identifier");
	struct value *v = parse_lookup(p, t->str);
	if (!v)
		parse_error(p, "the file '%s' is not open (or was read to its end)", t->str);
	if (v->kind != VAL_FILE)
		parse_error(p, "'%s' is a %s, not a file", t->str, val_kind_name(v->kind));
	if (v->file->writing != writing)
		parse_error(p, "the file '%s' was opened for %s", t->str, v->file->writing ? "writing" : "reading");
	parse_advance(p);
	return v->file;
}

/* One number with an optional sign from a file's tokens. */
static bool read_number(struct sdl_file *f, double *out)
{
	double sign = 1;
	size_t i = f->pos;
	while (i < f->ntoks && (f->toks[i].kind == TOK_MINUS || f->toks[i].kind == TOK_PLUS)) {
		if (f->toks[i].kind == TOK_MINUS)
			sign = -sign;
		i++;
	}
	if (i >= f->ntoks || f->toks[i].kind != TOK_NUMBER)
		return false;
	*out = sign * f->toks[i].num;
	f->pos = i + 1;
	return true;
}

static void unref_file(void *f)
{
	sdl_file_unref(f);
}

static void read_items(struct parser *p, struct srcpos at, const char *fname, struct sdl_file *f);

/* #read ( IDENT , VAR {, VAR} ) */
void parse_read(struct parser *p, struct srcpos at)
{
	parse_expect(p, TOK_LPAREN);
	const char *fname = parse_peek(p)->kind == TOK_IDENT ? parse_peek(p)->str : NULL;
	struct sdl_file *f = file_arg(p, false);
	/* Held while reading: the file's identifier is unbound at the end of
	 * the file, and a variable read into could be bound to it (through a
	 * macro parameter); found by fuzzing as a use after free. */
	f->refs++;
	int slot = parse_own(p, f, unref_file);
	read_items(p, at, fname, f);
	parse_release(p, slot);
	sdl_file_unref(f);
}

static void read_items(struct parser *p, struct srcpos at, const char *fname, struct sdl_file *f)
{
	while (parse_accept(p, TOK_COMMA)) {
		const struct token *t = parse_peek(p);
		if (t->kind != TOK_IDENT)
			parse_expected(p, "an identifier to read into");
		const char *var = t->str;
		/* POV-Ray: "Expected 'undeclared identifier', file identifier
		 * found instead" (#read (F, F, ...) freed the file being read). */
		const struct value *old = parse_lookup(p, var);
		if (old && old->kind == VAL_FILE)
			parse_error(p, "#read cannot read into '%s': it is a file identifier", var);
		parse_advance(p);
		while (f->pos < f->ntoks && f->toks[f->pos].kind == TOK_COMMA)
			f->pos++;
		if (f->pos >= f->ntoks || f->toks[f->pos].kind == TOK_EOF) {
			/* The end: the file's identifier goes away. */
			while (!parse_accept(p, TOK_RPAREN)) {
				if (parse_is(p, TOK_EOF)) /* found by fuzzing: it spun here */
					parse_expected(p, "')' to close #read");
				parse_advance(p);
			}
			struct value *fv = parse_lookup(p, fname);
			if (fv && fv->kind == VAL_FILE)
				parse_unbind(p, fname);
			return;
		}
		const struct token *it = &f->toks[f->pos];
		struct value v;
		double x;
		if (it->kind == TOK_STRING) {
			v = (struct value){.kind = VAL_STRING, .str = it->str, .pos = at};
			f->pos++;
		} else if (it->kind == TOK_LT) {
			double c[5];
			int n = 0;
			f->pos++;
			for (;;) {
				if (n == 5 || !read_number(f, &c[n]))
					parse_error_at(p, at, "#read: a vector in \"%s\" is malformed", f->name);
				n++;
				if (f->pos < f->ntoks && f->toks[f->pos].kind == TOK_COMMA) {
					f->pos++;
					continue;
				}
				if (f->pos < f->ntoks && f->toks[f->pos].kind == TOK_GT) {
					f->pos++;
					break;
				}
				parse_error_at(p, at, "#read: a vector in \"%s\" is malformed", f->name);
			}
			if (n < 2)
				parse_error_at(p, at, "#read: a vector in \"%s\" has fewer than 2 components", f->name);
			v = val_vector(n, c, VAL_VECTOR, at);
		} else if (read_number(f, &x)) {
			v = val_float(x, at);
		} else {
			char buf[128];
			parse_error_at(p, at, "#read: cannot read %s from \"%s\" (only numbers, vectors and strings)",
			               lex_describe(it, buf, sizeof buf), f->name);
		}
		parse_assign(p, var, false, v);
		/* An item the end of the file follows directly is the last: the
		 * file's identifier goes away now (POV-Ray's behaviour). */
		if (f->pos >= f->ntoks || f->toks[f->pos].kind == TOK_EOF) {
			parse_expect(p, TOK_RPAREN);
			parse_unbind(p, fname);
			return;
		}
	}
	parse_expect(p, TOK_RPAREN);
}

/* v as a binary word of `bytes` bytes: rounded (floor(v + 0.5)) and held
 * to the word's range, as POV-Ray 3.7 writes it (measured: uint8 3.7 gives
 * 4, 2.5 gives 3, 300 gives 255, -0.6 gives 0; sint8 -2.5 gives -2, -200
 * gives -128; sint16le 1e300 gives 32767). NaN is written as 0. */
static void put_word(FILE *fp, double v, int bytes, bool is_signed, bool big)
{
	double hi = is_signed ? ldexp(1, 8 * bytes - 1) - 1 : ldexp(1, 8 * bytes) - 1;
	double lo = is_signed ? -hi - 1 : 0;
	double r = floor(v + 0.5);
	long long x = 0;
	if (r > hi)
		x = (long long)hi;
	else if (r < lo)
		x = (long long)lo;
	else if (r == r)
		x = (long long)r;
	for (int i = 0; i < bytes; i++) {
		int shift = big ? (bytes - 1 - i) * 8 : i * 8;
		fputc((int)((unsigned long long)x >> shift) & 0xff, fp);
	}
}

/* #write ( IDENT , item {, item} ) : strings as they are, floats and
 * vectors as POV-Ray prints them (%g), or binary words after uint8,
 * sint16be, ... */
void parse_write(struct parser *p)
{
	parse_expect(p, TOK_LPAREN);
	struct sdl_file *f = file_arg(p, true);
	/* Held while writing, as #read holds its file: a #fclose among the
	 * arguments freed it (found by fuzzing as a use after free). */
	f->refs++;
	int slot = parse_own(p, f, unref_file);
	while (parse_accept(p, TOK_COMMA)) {
		int bytes = 0;
		bool big = false, is_signed = false;
		const struct token *t = parse_peek(p);
		if (t->kind == TOK_KEYWORD) {
			switch (t->kw) {
			case KW_UINT8: bytes = 1; break;
			case KW_SINT8: bytes = 1; is_signed = true; break;
			case KW_UINT16BE: bytes = 2; big = true; break;
			case KW_SINT16BE: bytes = 2; big = true; is_signed = true; break;
			case KW_UINT16LE: bytes = 2; break;
			case KW_SINT16LE: bytes = 2; is_signed = true; break;
			case KW_SINT32BE: bytes = 4; big = true; is_signed = true; break;
			case KW_SINT32LE: bytes = 4; is_signed = true; break;
			default: break;
			}
			if (bytes)
				parse_advance(p);
		}
		struct value v = parse_expression(p);
		if (!f->fp) {
			parse_drop(p, &v);
			parse_error(p, "#write's file was closed among its arguments");
		}
		if (bytes) {
			parse_need_float(p, &v, "a binary #write");
			put_word(f->fp, v.v[0], bytes, is_signed, big);
			continue;
		}
		switch (v.kind) {
		case VAL_STRING:
			/* Non-ASCII characters as spaces, as POV-Ray writes them. */
			for (const char *c = v.str; *c;) {
				size_t l;
				ustr_get(c, &l);
				fputc((unsigned char)*c < 0x80 ? *c : ' ', f->fp);
				c += l;
			}
			break;
		case VAL_FLOAT: fprintf(f->fp, "%g", v.v[0]); break;
		case VAL_VECTOR: case VAL_COLOR:
			fputc('<', f->fp);
			for (int i = 0; i < v.n; i++)
				fprintf(f->fp, i ? ",%g" : "%g", v.v[i]);
			fputs("> ", f->fp);
			break;
		default: {
			const char *kind = val_kind_name(v.kind);
			parse_drop(p, &v);
			parse_error(p, "#write cannot write a %s", kind);
		}
		}
	}
	parse_expect(p, TOK_RPAREN);
	if (f->fp)
		fflush(f->fp);
	parse_release(p, slot);
	sdl_file_unref(f);
}

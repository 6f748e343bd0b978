/* parser.h: the parser's state, shared by the files of the front end
 * (parse.c: token stream and directives; expr.c: expressions; stmt.c:
 * scene statements). Not for use outside src/lang/. */
#ifndef LUCENT_PARSER_H
#define LUCENT_PARSER_H

#include "lang/exprcache.h"
#include "lang/lex.h"
#include "lang/parse.h"
#include "lang/sym.h"
#include "lang/value.h"

#include <setjmp.h>

/* Limits. The nesting of includes and macro calls, expressions, CSG and
 * the sizes of arrays, strings and meshes are in parse_opts.limits (the
 * user can raise them); these are fixed. */
enum { MAX_OWNED = 4096, MAX_CONDS = 4096, MAX_DIRECTIVE_DEPTH = 256 };

enum frame_kind { FRAME_FILE, FRAME_MACRO };

/* A source of tokens being read: a file or a macro body. */
struct frame {
	enum frame_kind kind;
	uint32_t file;
	const struct token *toks;
	size_t pos, end;       /* next token; one past the last (a macro's #end) */
	struct srcpos from;    /* where it was entered (the #include or the call) */
	const char *macro;     /* the macro's name, for FRAME_MACRO */
	struct symtab *locals; /* #local scope; NULL for the main file */
	int nconds;            /* open #if/#while/... when the frame was entered */
};

enum cond_kind { COND_IF, COND_SWITCH, COND_WHILE, COND_FOR };

/* An open #if, #switch, #while or #for, waiting for its #end. */
struct cond {
	enum cond_kind kind;
	int frame;            /* the frame it belongs to */
	struct srcpos pos;    /* of the directive, for "never closed" errors */
	size_t loop;          /* WHILE: index of its '#'; FOR: the body's first token */
	const char *var;      /* FOR: the loop variable */
	double end, step;     /* FOR */
	double value;         /* SWITCH: the value switched on */
	bool matched;         /* SWITCH: a #case has matched (later ones fall through) */
	unsigned serial;      /* which push made it (cond_intact) */
};

/* Something to free if the parse fails before it is handed on. */
struct owned {
	void *ptr;
	void (*free)(void *);
};

enum { DECL_CACHE = 64 };

struct parser {
	struct srcmgr *sm;
	struct diag *d;
	const struct parse_opts *o;
	struct scene *scene;
	struct interner *names;
	jmp_buf *boundary;           /* where errors unwind to */

	struct parse_limits lim;     /* o->limits with the defaults filled in */
	struct frame *frames;        /* lim.macro_depth + lim.include_depth + 1 */
	int nframes, capframes;
	size_t csg_depth;            /* CSG objects open around the current one */
	struct cond conds[MAX_CONDS];
	int nconds;
	unsigned cond_serial;        /* pushes so far, numbering the conds */
	bool interrupted;            /* stopped through o->stop */
	bool defer;                  /* reading a directive's operands (see
	                              * parse_peek_cont) */
	struct token cur;            /* the lookahead token, valid if have_cur */
	bool have_cur;               /* tokens are fetched lazily, so a directive
	                              * after a statement runs only once the
	                              * statement is complete */
	struct token prev;           /* the token consumed last, for positions */
	struct srcpos deprecated_at; /* the use of a deprecated identifier warned */
	unsigned long deprecated_ev; /* about last, and `events` then (one warning a use) */
	const struct value *cur_elem; /* the array element the lookahead
	                              * identifier stands for after A[i]... was
	                              * read (parse_ident_value), valid while that
	                              * token at cur_elem_at is the lookahead */
	struct srcpos cur_elem_at;

	struct symtab *globals;
	double version;
	int expr_depth;
	/* Comparisons, '&', '|' and '?:' bind only inside parentheses (a
	 * group or a call's argument list), as in POV-Ray: at the top level a
	 * '<' after a complete value begins the next vector, so that
	 * `box { <0,0,0> <1,1,1> }` is two corners. */
	bool rel_ok;
	int directive_depth;         /* directives inside directives' operands */

	char debug_buf[161];         /* #debug text not yet written: POV-Ray */
	int debug_len;               /* buffers 160 characters (directive.c) */
	uint32_t *rng;               /* rand() streams made by seed() */
	int nrng, caprng;

	struct owned owned[MAX_OWNED];
	int nowned;
	struct texture *default_tex; /* #default { texture }: one reference */
	struct exprcache *xcache;    /* compiled float expressions (exprcache.h) */
	struct font_cache *fonts;    /* the fonts text statements loaded (text_parse.c) */
	unsigned long steps;         /* directives run and macros called (parse_step) */
	unsigned long events;        /* directives run and frames entered or left */
	unsigned long bindgen;       /* bumped when any binding is added or removed or a
	                              * frame is entered or left: pointers to bindings
	                              * taken at one value stay valid while it holds */
	struct symtab *spare_locals; /* an empty table kept for the next macro call */
	struct sym_gen lookgen;      /* finer: a name's lookup stands while its bucket's
	                              * generation holds (sym.h); compiled expressions keep
	                              * their variables' bindings across macro calls */
	unsigned long writes;        /* files opened by #fopen for writing or appending:
	                              * an #include of a file loaded before the last
	                              * such #fopen reads it again */
	struct decl_cache {          /* the slot each recent #declare/#local wrote */
		const struct token *site;    /* the declared identifier's token */
		struct value *slot;
		unsigned long gen;           /* local: bindgen when slot was found; else
		                              * the name's bucket's generation in lookgen */
		unsigned bucket;             /* sym_gen_bucket of the name */
		bool local;
	} declcache[DECL_CACHE];
};

/* Errors: report at pos (or at the current token) and unwind. */
_Noreturn void parse_error_at(struct parser *p, struct srcpos pos, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
_Noreturn void parse_error(struct parser *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Count one step (a directive or a macro call at pos; loop_head: the
 * directive is a #while) against o->max_steps, and stop if o->stop is
 * set: "interrupted" with the innermost loop, and the parse returns 2. */
void parse_step(struct parser *p, struct srcpos pos, bool loop_head);
/* "expected X, found Y" at the current token. */
_Noreturn void parse_expected(struct parser *p, const char *what);
void parse_warning_at(struct parser *p, struct srcpos pos, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

/* Is s a rand() stream: a number whose truncation toward zero indexes one
 * that seed() made? Checked as a float (a huge s does not fit a long); with
 * no stream at all, even -0.5 (index 0) has none. */
static inline bool parse_rng_stream(const struct parser *p, double s)
{
	return p->nrng > 0 && s > -1 && s < p->nrng;
}

/* Set whether comparisons bind (struct parser's rel_ok); returns the old
 * setting, for the caller to put back. */
static inline bool parse_set_rel(struct parser *p, bool on)
{
	bool old = p->rel_ok;
	p->rel_ok = on;
	return old;
}

/* The token stream (directives already run). parse_peek returns the
 * current token, fetching it if needed; parse_advance consumes it. The
 * common cases are inline (a parse reads every token through them);
 * parse_peek_fetch is the rest of parse_peek: it runs the directives and
 * macro calls before the next token. */
const struct token *parse_peek_fetch(struct parser *p);
static inline const struct token *parse_peek(struct parser *p)
{
	if (p->have_cur && p->cur.kind != TOK_HASH)
		return &p->cur;
	return parse_peek_fetch(p);
}
/* The lookahead where a value could continue (an operator, '.', ';'...).
 * While a directive's operands are read, a directive there does not run
 * yet: it shows as TOK_HASH, so `#declare A = 1; #declare B = A;` and
 * `#if (A) #declare ...` act in order. */
const struct token *parse_peek_cont(struct parser *p);
/* The next token as it stands, without running a directive or a macro
 * call first: the lookahead if one was taken, else the top frame's next
 * token (NULL at the frame's end). */
const struct token *parse_peek_raw(struct parser *p);
static inline void parse_advance(struct parser *p)
{
	p->prev = *parse_peek(p);
	p->have_cur = false;
}
static inline bool parse_is(struct parser *p, enum tok_kind k) { return parse_peek(p)->kind == k; }
static inline bool parse_is_kw(struct parser *p, enum kw k)
{
	const struct token *t = parse_peek(p);
	return t->kind == TOK_KEYWORD && t->kw == k;
}
/* Take the next token if it is of kind k. With no lookahead held, a kind
 * that runs nothing before it (not '#', not an identifier, which may be a
 * macro call) is taken from the frame in place. */
static inline bool parse_accept(struct parser *p, enum tok_kind k)
{
	if (!p->have_cur && k != TOK_HASH && k != TOK_IDENT) {
		struct frame *f = &p->frames[p->nframes - 1];
		if (f->pos < f->end && f->toks[f->pos].kind == k) {
			p->prev = f->toks[f->pos++];
			return true;
		}
	}
	if (parse_peek(p)->kind != k)
		return false;
	parse_advance(p);
	return true;
}
static inline bool parse_accept_kw(struct parser *p, enum kw k)
{
	if (!parse_is_kw(p, k))
		return false;
	parse_advance(p);
	return true;
}
/* parse_accept, or an error "expected 'K'". */
void parse_expect_fail(struct parser *p, enum tok_kind k);
static inline void parse_expect(struct parser *p, enum tok_kind k)
{
	if (!parse_accept(p, k))
		parse_expect_fail(p, k);
}

/* Ownership during a parse: protect a pointer until released. */
int parse_own(struct parser *p, void *ptr, void (*fn)(void *));
void parse_release(struct parser *p, int slot);

/* "undefined identifier 'X'", suggesting the nearest declared name. */
_Noreturn void parse_undefined(struct parser *p, const char *name);
/* If the current token is an identifier, its value (an undefined one is
 * an error); otherwise NULL. Does not consume it. */
const struct value *parse_ident_value(struct parser *p);
/* Gives the warning of a `#declare deprecated` identifier v, named name and
 * used at at (once in all if it was declared `once`), and only once for one
 * use however often the token is looked at; does nothing for others. */
void parse_note_use(struct parser *p, struct value *v, const char *name, struct srcpos at);
/* "'X' is a K, not WANT" about the identifier at the current token. */
_Noreturn void parse_wrong_kind(struct parser *p, const struct value *v, const char *want);
/* Symbols: the innermost binding of name (aliases followed), or NULL. */
struct value *parse_lookup(struct parser *p, const char *name);
/* The innermost binding of name itself (a by-reference parameter is not
 * followed; the value may be VAL_NONE), or NULL. */
struct value *parse_binding(struct parser *p, const char *name);
/* The value slot #declare NAME (local: #local NAME) assigns: the
 * innermost existing binding, through by-reference parameters, else a new
 * one (global for #declare, at the current level for #local). */
struct value *parse_assign_slot(struct parser *p, const char *name, bool local);
/* Assign v (taking it) as #declare / #local does. */
void parse_assign(struct parser *p, const char *name, bool local, struct value v);
/* parse_assign_slot for the declaration of the identifier token `site`
 * (in a token array): the slot found last time there is reused while it
 * stands (#local: no binding added or removed and no frame entered or
 * left; #declare: the name's lookup generations hold). */
struct value *parse_declare_slot_find(struct parser *p, const struct token *site, bool local);
static inline struct value *parse_declare_slot(struct parser *p, const struct token *site, bool local)
{
	const struct decl_cache *c = &p->declcache[((uintptr_t)site / sizeof *site) & (DECL_CACHE - 1)];
	/* A #declare's slot is the name's lookup (sym.h's generations hold it
	 * across macro calls); a #local's is in the innermost table, which
	 * any frame entered or left may change. */
	if (c->site == site && c->local == local && c->gen == (local ? p->bindgen : p->lookgen.name[c->bucket]))
		return c->slot;
	return parse_declare_slot_find(p, site, local);
}
/* The table holding the binding that NAME refers to for a by-reference
 * parameter (aliases followed); *name becomes the name there. */
struct symtab *parse_alias_target(struct parser *p, const char **name);
/* Remove the innermost binding of name (#undef); false if there is none. */
bool parse_unbind(struct parser *p, const char *name);
/* The innermost #local table (the globals in the main file). */
struct symtab *parse_local_table(struct parser *p);
/* Close the frames above frame index `home` whose tokens are all read.
 * A value read from its compiled form (exprcache.h) reads a macro's last
 * tokens in place and leaves the finished macro's frame on the stack; a
 * #declare or #local must not bind into it. Does nothing while a
 * lookahead token is held (it was read past those frames already). */
void parse_leave_finished(struct parser *p, int home);

/* Raw token access for directives: the next token of the innermost frame,
 * without running directives or macros. Only when no lookahead is held.
 * The common case (the frame has tokens left) is inline; parse_raw_next
 * leaves finished frames. */
struct token parse_raw_next(struct parser *p);
static inline struct token parse_raw(struct parser *p)
{
	struct frame *f = &p->frames[p->nframes - 1];
	if (f->pos < f->end)
		return f->toks[f->pos++];
	return parse_raw_next(p);
}
/* Enter a macro body (called by the token stream on a macro's name). */
void parse_call_macro(struct parser *p, const struct token *name, struct macro *m);
/* Enter a file's tokens; `from` is the #include's position. */
void parse_push_file(struct parser *p, uint32_t file, struct srcpos from);
/* Run a directive whose '#' was at index `at` of the top frame. */
void parse_directive(struct parser *p, size_t at);
/* Values of scene items found while evaluating an expression are owned by
 * the parse until a consumer takes them. */
void parse_take(struct parser *p, struct value *v);
void parse_drop(struct parser *p, struct value *v);

/* Expressions (expr.c). */
struct value parse_expression(struct parser *p);
double parse_float(struct parser *p);
/* A float where POV-Ray takes a C int: truncated, and INT_MIN outside the
 * int's range and for NaN (what POV-Ray's cast gives on x86), never the
 * undefined cast (found by fuzzing: dispersion_samples 5.6e22). */
int parse_int_of(double x);
vec3 parse_vector(struct parser *p);
struct rgbft parse_color(struct parser *p);
/* Is the current token the start of an expression? */
bool parse_starts_expression(struct parser *p);
/* A string: a literal, a string identifier or a string function call. It
 * reads nothing past its last token (so #include can enter the file at
 * once). */
const char *parse_string(struct parser *p);
/* '<' FLOAT { ',' FLOAT } '>' with up to max entries (matrix, and lists
 * longer than a vector); returns how many were read. */
int parse_number_list(struct parser *p, double *out, int max);

/* '[' INT ']' for each dimension of array a (named name, at at): the
 * flat index of the element, range-checked (directive.c). */
size_t parse_array_index(struct parser *p, const struct array *a, const char *name, struct srcpos at);

/* Built-in functions (builtin.c): is k one, and call it (the current
 * token is its name). */
bool builtin_is_function(enum kw k);
/* The float functions of one or two floats (sin, pow, degrees, ...),
 * shared by expressions and function bodies. */
struct math_fn {
	enum kw kw;
	int nargs;
	double (*f1)(double);
	double (*f2)(double, double);
};
const struct math_fn *builtin_math_fn(enum kw k);
/* IDENT or IDENT[i]...: is it declared (the element set)? Reads the
 * identifier and its indices. */
bool parse_defined(struct parser *p);
struct value builtin_call(struct parser *p);
/* POV-Ray's comparison and logic operators (expr.c), in one order that
 * the expression parser and the compiled expressions (exprcache.c) share:
 * values within 1e-10 are equal, and within 1e-10 of zero are false. */
enum parse_cmp { CMP_OR, CMP_AND, CMP_LT, CMP_LE, CMP_EQ, CMP_GE, CMP_GT, CMP_NE };
bool parse_truthy(double x);
double parse_compare(enum parse_cmp op, double x, double y);
/* The colour the keyword k (rgb, rgbf, rgbt, rgbft, srgb...) makes of the
 * operand v[0..n) (a float, is_float, fills every component; a vector is
 * padded with zeros), into c[5]. */
void parse_keyword_color(enum kw k, const double *v, int n, bool is_float, double c[5]);
/* Typed operands for built-ins and statements. */
void parse_need_float(struct parser *p, const struct value *v, const char *what);
void parse_need_numeric(struct parser *p, const struct value *v, const char *what);
const char *parse_intern(struct parser *p, const char *s, size_t n);
/* A width, precision or count argument of str() or vstr() as an int,
 * saturated to +-1000 (a NaN is 0): the float may be anything. */
int parse_format_arg(double x);
/* A number formatted as POV-Ray's str(x, l, prec) does. */
const char *parse_format_float(struct parser *p, double x, int l, int prec);

/* User functions (func.c): `function [(params)] { body }` after the
 * keyword, and calling one from an expression. */
struct fn *parse_function(struct parser *p);
/* The same from the '{' on, with the parameters x, y, z (the body of
 * image_map { function W, H { ... } }). */
struct fn *parse_function_body(struct parser *p);
struct value parse_call_function(struct parser *p, const struct fn *f, struct srcpos at);
/* Splines (func.c): `spline { ... }` and evaluating S(t). */
struct spline *parse_spline(struct parser *p);
struct value spline_eval(const struct spline *s, double t, struct srcpos at);
/* Evaluate as another spline type (enum spline_kind), or its own if < 0. */
struct value spline_eval_as(const struct spline *s, double t, int kind, struct srcpos at);

/* The string literal s (a token's text) as POV-Ray reads it under the
 * charset in force now: under ascii each byte of the file that is not
 * ASCII becomes a space, with a warning (measured: asc() gives 32, and a
 * string read before `charset utf8` keeps its spaces). Returns s itself
 * or an interned copy (text_parse.c). */
const char *parse_charset_literal(struct parser *p, const char *s, struct srcpos at);

/* Find a file the scene names (#include, image files) as POV-Ray does:
 * relative to the folder of file from_file, then the current folder, then
 * each +L path, then lucent's stdlib (directive.c). Returns a malloc'd
 * path, or NULL if it is not there. */
char *parse_find_file(struct parser *p, const char *name, uint32_t from_file);

/* Write one #debug message, wrapping lines at 80 columns as POV-Ray does
 * (see directive.c for the rule); text is written when a line ends or
 * the stream's buffer is full.
 * parse_debug_flush ends the stream: like POV-Ray, it drops a last line
 * that no newline ended. */
void parse_debug_write(struct parser *p, const char *text);
void parse_debug_flush(struct parser *p);

/* #default { ... } (texture_parse.c). */
void parse_default(struct parser *p);

/* The file rule (fileio.c): a scene may read files in its own folder,
 * the +L paths and the stdlib, and write only in its
 * own folder, unless o->io_unrestricted. path is the file as found
 * (resolved here: links and '..' followed), name as the scene wrote it,
 * what the directive or item ("#include"); an error at `at` otherwise. */
void parse_check_access(struct parser *p, const char *path, const char *name, bool writing, const char *what,
                        struct srcpos at);
/* File directives (fileio.c); the current token follows the keyword. */
void parse_fopen(struct parser *p, struct srcpos at);
void parse_fclose(struct parser *p);
void parse_read(struct parser *p, struct srcpos at);
void parse_write(struct parser *p);

/* Textures (texture_parse.c; finishes and interiors in finish_parse.c):
 * read into what they are given. parse_texture
 * replaces *tex; parse_private_texture makes *tex one this holder may
 * change alone (created from the #default texture if NULL) and returns it.
 * parse_free_texture_holder frees a heap `struct texture *` holder and its
 * reference (for parse_own). */
void parse_texture(struct parser *p, struct texture **tex);
/* A texture statement layered on top of *tex (NULL: none yet), as
 * several texture statements on one object are. */
void parse_texture_layer(struct parser *p, struct texture **tex);
/* Make the texture *tex (its top layer, made private) uv-mapped, as
 * `texture { uv_mapping ... }` is (whole), or only its pattern, pigment
 * and normal; an object's `uv_mapping` does this to each texture (whole),
 * pigment or normal given after it. */
void texture_uv_mapping(struct texture **tex, bool whole);
/* Patterns (pattern_parse.c). parse_at_pattern: is the current token a
 * pattern keyword (its kind in *k)? parse_pattern_type replaces *pt by the
 * pattern there with its arguments, for the given use (facets only in a
 * normal); an `object` pattern's list and '}' are left to the caller.
 * parse_pattern_modifier reads one modifier into *pt and returns true, or
 * reads nothing and returns false. parse_pattern_block reads
 * '{' PATTERN { pattern_modifier | transformation } '}' (the body of
 * function { pattern { } }) into *pt. parse_pattern_end makes the checks
 * that need all of a pattern's modifiers; the body's closing token is the
 * current one (for error positions). */
enum pattern_use { PATTERN_IN_PIGMENT, PATTERN_IN_NORMAL, PATTERN_IN_TEXTURE };
bool parse_at_pattern(struct parser *p, enum pattern_kind *k);
void parse_pattern_type(struct parser *p, struct pattern *pt, enum pattern_use use);
bool parse_pattern_modifier(struct parser *p, struct pattern *pt);
void parse_pattern_block(struct parser *p, struct pattern *pt);
void parse_pattern_end(struct parser *p, const struct pattern *pt);
/* A pigment body (what follows `pigment {`) up to and including `end`,
 * from black; the caller owns the result (texture_parse.c). */
struct pigment *parse_pigment_body(struct parser *p, enum tok_kind end);
/* The layers of top (copied where shared) with under below its last
 * layer; takes both references and returns the result's. */
struct texture *parse_layer_onto(struct texture *top, struct texture *under);
/* texture { } { texture { } } as a declared value (layered when several
 * follow); the caller owns the result. */
struct texture *parse_texture_value(struct parser *p);
/* pigment { } and normal { } as declared values; the caller owns them. */
struct pigment *parse_pigment_value(struct parser *p);
struct normal *parse_normal_value(struct parser *p);
void parse_pigment(struct parser *p, struct pigment **pig);
/* normal { }: replaces or modifies *nrm (NULL: none yet). */
void parse_normal(struct parser *p, struct normal **nrm);
/* material { }: its texture and interior into *m (references replaced). */
void parse_material(struct parser *p, struct material *m);
/* color_map, colour_map, pigment_map, normal_map, slope_map or
 * texture_map { } at the current token; the caller owns the result. */
struct blend_map *parse_map_value(struct parser *p);
void parse_finish(struct parser *p, struct finish *f);
void parse_interior(struct parser *p, struct interior **in);
/* The inside of an image_map, bump_map, image_pattern or material_map
 * block after its '{' up to the image's modifiers (image_parse.c): the
 * file type and name and the mapping modifiers, into m. Stops at the
 * first token it does not know (the caller's own items, or '}'). */
void parse_image_mapping(struct parser *p, struct image_mapping *m);
struct texture *parse_private_texture(struct parser *p, struct texture **tex);
void parse_free_texture_holder(void *holder);

/* Objects and transformations (objects.c). */
/* Does keyword k begin an object statement? */
bool parse_is_object_start(enum kw k);
/* An object statement at the current token; scene_level applies the
 * #default texture to what has none (declared objects get it when they
 * are placed). The caller owns the result. */
struct object *parse_object(struct parser *p, bool scene_level);
/* polygon, lathe, sor and isosurface (objects2.c): is k one of them; the
 * statement's arguments after its '{' (the caller owns the result); and
 * its `open` or `sturm` modifier (false if k takes no such modifier). */
bool parse_is_object2(enum kw k);
struct object *parse_object2(struct parser *p, enum kw k, struct srcpos at);
bool parse_object2_flag(struct object *o, enum kw k, bool is_open, bool on);
/* blob, height_field and sphere_sweep (objects3.c): is k one of them; the
 * statement's arguments after its '{' (the caller owns the result); and
 * one of the object's own modifiers at the current token (sturm,
 * hierarchy...), read into o (false, nothing read, if there is none). */
bool parse_is_object3(enum kw k);
struct object *parse_object3(struct parser *p, enum kw k, struct srcpos at);
bool parse_object3_modifier(struct parser *p, struct object *o, enum kw k);
/* A transformation (translate, rotate, scale, matrix, transform) at the
 * current token into *out; false if there is none. */
bool parse_transform_item(struct parser *p, struct xform *out);
/* text { ... } from the token after '{' up to its modifiers
 * (text_parse.c); at is the statement's position. The caller owns it. */
struct object *parse_text(struct parser *p, struct srcpos at);
/* Free the fonts the parse's text statements loaded (text_parse.c). */
void parse_fonts_free(struct parser *p);
/* `transform` { ... } | IDENT as a value; the caller owns the result. */
struct xform *parse_transform_value(struct parser *p);

/* The scene-wide statements (atmos_parse.c): background, fog, sky_sphere,
 * rainbow and global_settings. parse_atmos_statement reads one at the
 * current token into the scene (false if the token begins none);
 * parse_atmos_value reads a fog, sky_sphere or rainbow as a #declare value
 * into *out (false if the token begins none). */
bool parse_atmos_statement(struct parser *p);
bool parse_atmos_value(struct parser *p, struct value *out);

/* Lights (light_parse.c). */
/* light_source { ... } at the current token into *l (which the caller
 * owns and protects, with parse_free_light, objects included). */
void parse_light(struct parser *p, struct light *l);
/* A light_source statement added to the scene (its looks_like object too). */
void parse_light_statement(struct parser *p);
/* light_group { ... } at the current token: the union of its objects; its
 * lights go into the scene. `child` as for parse_object's !scene_level.
 * The caller owns the result. */
struct object *parse_light_group(struct parser *p, bool child);
/* Give the leaves of o, a copy of a declared object being placed, copies
 * of the light groups they are in and of those groups' lights (added to
 * the scene), so that this placement's transformations move them. */
void parse_place_light_groups(struct parser *p, struct object *o);
/* light_source { ... } at the current token, in the body of CSG csg: a
 * global light that csg carries (see light_parse.c). */
void parse_csg_light(struct parser *p, struct object *csg);
/* Apply t to the scene's lights from number `from` on: the lights read
 * inside an object statement move with its transformations. */
void parse_move_lights(struct parser *p, size_t from, const struct xform *t);
/* Free a heap `struct light` and what it owns (for parse_own). */
void parse_free_light(void *light);

/* The camera statement at the `camera` keyword, into c (which holds the
 * camera to start from, camera_default()) (camera_parse.c). The caller
 * owns c's references (camera_clear), also when the parse fails. */
void parse_camera(struct parser *p, struct camera *c);

/* Statements (stmt.c). */
void parse_statement(struct parser *p);
/* A scene-item value for #declare when the right-hand side is not an
 * expression (sphere {...}, pigment {...}); false if not one. */
bool parse_item_value(struct parser *p, struct value *out);
/* Any right-hand side of a declaration: a scene item or an expression
 * (taken from the parse's ownership). */
struct value parse_rvalue(struct parser *p);

#endif

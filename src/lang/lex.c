/* lex.c: the hand-written lexer (see lex.h). */
#include "lang/lex.h"

#include "lang/ustr.h"

#include "lang/intern.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct lexer {
	struct srcmgr *sm;
	struct diag *d;
	uint32_t file;
	const char *s;     /* text */
	size_t n, i;       /* length, offset */
	uint32_t line;
	size_t line_start; /* offset of the current line's first byte */
	struct token *toks;
	size_t ntoks, cap;
	char *sbuf;        /* scratch for string literals */
	size_t scap;
	bool in_list;      /* inside the braces of a mesh2 list (see numlist) */
	void **blocks;     /* numlists made so far */
	size_t nblocks, bcap;
};

static struct srcpos here(const struct lexer *lx, size_t at)
{
	struct srcpos p = {lx->file, lx->line, (uint32_t)(at - lx->line_start + 1)};
	return p;
}

static struct token *push(struct lexer *lx, enum tok_kind k, struct srcpos pos)
{
	if (lx->ntoks == lx->cap) {
		lx->cap = lx->cap ? lx->cap * 2 : 256;
		lx->toks = realloc(lx->toks, lx->cap * sizeof *lx->toks);
		if (!lx->toks) abort();
	}
	struct token *t = &lx->toks[lx->ntoks++];
	memset(t, 0, sizeof *t);
	t->kind = (uint8_t)k;
	t->pos = pos;
	return t;
}

static void newline(struct lexer *lx, size_t at)
{
	lx->line++;
	lx->line_start = at + 1;
}

/* Skip white space and comments. Block comments nest, as in POV-Ray.
 * Returns false after reporting an unterminated comment. */
static bool skip_space_slow(struct lexer *lx)
{
	while (lx->i < lx->n) {
		char c = lx->s[lx->i];
		if (c == '\n') {
			newline(lx, lx->i);
			lx->i++;
		} else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
			lx->i++;
		} else if (c == '/' && lx->i + 1 < lx->n && lx->s[lx->i + 1] == '/') {
			while (lx->i < lx->n && lx->s[lx->i] != '\n')
				lx->i++;
		} else if (c == '/' && lx->i + 1 < lx->n && lx->s[lx->i + 1] == '*') {
			struct srcpos start = here(lx, lx->i);
			int depth = 0;
			while (lx->i < lx->n) {
				if (lx->s[lx->i] == '/' && lx->i + 1 < lx->n && lx->s[lx->i + 1] == '*') {
					depth++;
					lx->i += 2;
				} else if (lx->s[lx->i] == '*' && lx->i + 1 < lx->n && lx->s[lx->i + 1] == '/') {
					depth--;
					lx->i += 2;
					if (depth == 0)
						break;
				} else {
					if (lx->s[lx->i] == '\n')
						newline(lx, lx->i);
					lx->i++;
				}
			}
			if (depth != 0) {
				diag_report(lx->d, DIAG_ERROR, start, "unterminated comment: '/*' is never closed by '*/'");
				return false;
			}
		} else {
			break;
		}
	}
	return true;
}

/* skip_space_slow, with the common case (no space or comment here:
 * mesh2 lists written without blanks) decided inline. */
static inline bool skip_space(struct lexer *lx)
{
	if (lx->i < lx->n) {
		char c = lx->s[lx->i];
		if ((unsigned char)c > ' ' && c != '/')
			return true;
	}
	return skip_space_slow(lx);
}

static inline bool is_digit(char c)
{
	return (unsigned char)(c - '0') < 10;
}

/* strtod of the number text s[0..len). */
static double slow_number(const char *s, size_t len)
{
	char buf[128];
	if (len >= sizeof buf) {
		char *tmp = malloc(len + 1);
		if (!tmp) abort();
		memcpy(tmp, s, len);
		tmp[len] = 0;
		double v = strtod(tmp, NULL);
		free(tmp);
		return v;
	}
	memcpy(buf, s, len);
	buf[len] = 0;
	return strtod(buf, NULL);
}

/* The end of the number starting at s[i] (digits, '.', digits, exponent)
 * and, when out is not NULL, its value: exactly strtod's result, read in
 * the same pass. Plain decimals of up to 15 digits and no exponent take a
 * fast path: the digits form an integer below 2^53 and 10^k is exact, so
 * one correctly rounded division gives the correctly rounded value. */
/* Inlined everywhere, so that the lexer's check of a mesh2 run (out NULL)
 * compiles to a scan that does no arithmetic. */
static inline __attribute__((always_inline)) size_t scan_number(const char *s, size_t i, size_t n, double *out)
{
	const char *p = s + i, *e = s + n;
	uint64_t m = 0;
	while (p < e && is_digit(*p))
		m = m * 10 + (uint64_t)(*p++ - '0');
	size_t ndig = (size_t)(p - (s + i)), frac = 0;
	if (p < e && *p == '.') {
		const char *f = ++p;
		while (p < e && is_digit(*p))
			m = m * 10 + (uint64_t)(*p++ - '0');
		frac = (size_t)(p - f);
		ndig += frac;
	}
	bool exponent = false;
	if (p < e && (*p == 'e' || *p == 'E')) {
		const char *q = p + 1;
		if (q < e && (*q == '+' || *q == '-'))
			q++;
		if (q < e && is_digit(*q)) {
			while (q < e && is_digit(*q))
				q++;
			p = q;
			exponent = true;
		}
	}
	if (out) {
		static const double p10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
		                             1e12, 1e13, 1e14, 1e15};
		if (!exponent && ndig <= 15)
			*out = frac > 0 ? (double)m / p10[frac] : (double)m;
		else
			*out = slow_number(s + i, (size_t)(p - (s + i)));
	}
	return (size_t)(p - s);
}

static bool lex_number(struct lexer *lx)
{
	size_t start = lx->i;
	double v;
	lx->i = scan_number(lx->s, lx->i, lx->n, &v);
	struct token *t = push(lx, TOK_NUMBER, here(lx, start));
	t->num = v;
	return true;
}

/* ---- runs of literal vectors in mesh2 lists ---- */

/* Where the lexer stands, to come back to. */
struct mark {
	size_t i, line_start;
	uint32_t line;
};

static struct mark mark_of(const struct lexer *lx)
{
	struct mark m = {lx->i, lx->line_start, lx->line};
	return m;
}

static void mark_restore(struct lexer *lx, struct mark m)
{
	lx->i = m.i;
	lx->line_start = m.line_start;
	lx->line = m.line;
}

/* A signed number at lx->i (no space between sign and digits, as in the
 * vectors exporters write), its value into *out unless out is NULL (the
 * lexer only checks the run; the parser reads the values); false, reading
 * nothing, if there is none. */
static inline __attribute__((always_inline)) bool run_number(struct lexer *lx, double *out)
{
	const char *s = lx->s;
	size_t i = lx->i, n = lx->n;
	bool neg = false;
	if (i < n && (s[i] == '-' || s[i] == '+')) {
		neg = s[i] == '-';
		i++;
	}
	if (!(i < n && (is_digit(s[i]) || (s[i] == '.' && i + 1 < n && is_digit(s[i + 1])))))
		return false;
	double v;
	size_t end = scan_number(s, i, n, out ? &v : NULL);
	/* A letter or '_' right after would make this something else. */
	if (end < n && ((unsigned char)((s[end] | 32) - 'a') < 26 || s[end] == '_'))
		return false;
	if (out)
		*out = neg ? -v : v;
	lx->i = end;
	return true;
}

/* One vector `<n, n[, n]>` into v (NULL: only checked); returns its size
 * (2 or 3) or 0, after which the caller restores the position. */
static inline __attribute__((always_inline)) int run_vector(struct lexer *lx, double v[3])
{
	lx->i++; /* '<' */
	int k = 0;
	for (;;) {
		if (!skip_space(lx) || k == 3 || !run_number(lx, v ? &v[k] : NULL))
			return 0;
		k++;
		if (!skip_space(lx) || lx->i >= lx->n)
			return 0;
		char c = lx->s[lx->i];
		if (c == '>') {
			lx->i++;
			return k >= 2 ? k : 0;
		}
		if (c != ',')
			return 0;
		lx->i++;
	}
}

/* At a '<' inside a mesh2 list: check the longest run of literal vectors
 * of one size that are not operands of an operator (a vector followed by
 * '*' or '-' is left to the expression parser), and push it as one
 * TOK_NUMLIST token. Returns false, reading nothing, if the first vector
 * does not qualify. */
static bool lex_run(struct lexer *lx)
{
	struct numlist l = {.start = lx->i, .line_start = lx->line_start, .line = lx->line};
	struct srcpos first = here(lx, lx->i);
	int dim = 0;
	for (;;) {
		struct mark start = mark_of(lx);
		int k = lx->i < lx->n && lx->s[lx->i] == '<' ? run_vector(lx, NULL) : 0;
		if (k == 0 || (dim && k != dim)) {
			mark_restore(lx, start);
			break;
		}
		/* What follows must end the item: a comma, another vector, the
		 * list's '}', a texture index or a directive. */
		struct mark after = mark_of(lx);
		if (!skip_space(lx)) {
			mark_restore(lx, start);
			break;
		}
		char c = lx->i < lx->n ? lx->s[lx->i] : 0;
		if (!(c == ',' || c == '<' || c == '}' || c == '#' || isdigit((unsigned char)c))) {
			mark_restore(lx, start);
			break;
		}
		dim = k;
		l.count++;
		if (c == ',')
			lx->i++;
		else if (c != '<')
			mark_restore(lx, after);
		if (!skip_space(lx)) {
			mark_restore(lx, after);
			break;
		}
	}
	if (l.count == 0)
		return false;
	l.dim = (uint32_t)dim;
	struct numlist *copy = malloc(sizeof *copy);
	if (!copy) abort();
	*copy = l;
	if (lx->nblocks == lx->bcap) {
		lx->bcap = lx->bcap ? 2 * lx->bcap : 8;
		lx->blocks = realloc(lx->blocks, lx->bcap * sizeof *lx->blocks);
		if (!lx->blocks) abort();
	}
	lx->blocks[lx->nblocks++] = copy;
	struct token *t = push(lx, TOK_NUMLIST, first);
	t->list = copy;
	return true;
}

void lex_numlist_begin(struct numlist_iter *it, const struct srcmgr *sm, uint32_t file, const struct numlist *l)
{
	const struct srcfile *f = sm->files[file];
	it->s = f->text;
	it->n = f->len;
	it->i = l->start;
	it->line_start = l->line_start;
	it->line = l->line;
	it->file = file;
}

void lex_numlist_next(struct numlist_iter *it, double v[3], struct srcpos *pos)
{
	/* The run was checked when it was lexed: read it again the same way. */
	struct lexer lx = {.s = it->s, .n = it->n, .i = it->i, .line = it->line, .line_start = it->line_start,
	                   .file = it->file};
	skip_space(&lx);
	*pos = here(&lx, lx.i);
	run_vector(&lx, v);
	skip_space(&lx);
	if (lx.i < lx.n && lx.s[lx.i] == ',')
		lx.i++;
	it->i = lx.i;
	it->line = lx.line;
	it->line_start = lx.line_start;
}

/* Can a '<' here begin an item of a mesh2 list, not an operand? After '{',
 * ',', a number (the count, a texture index) or the '>' of a vector. */
static bool starts_item(const struct lexer *lx)
{
	if (lx->ntoks == 0)
		return false;
	switch (lx->toks[lx->ntoks - 1].kind) {
	case TOK_LBRACE: case TOK_COMMA: case TOK_NUMBER: case TOK_GT: case TOK_NUMLIST:
		return true;
	default:
		return false;
	}
}

/* Does the token before the '{' just pushed open a mesh2 list? */
static bool opens_list(const struct lexer *lx)
{
	if (lx->ntoks < 2)
		return false;
	const struct token *k = &lx->toks[lx->ntoks - 2];
	if (k->kind != TOK_KEYWORD)
		return false;
	switch (k->kw) {
	case KW_VERTEX_VECTORS: case KW_NORMAL_VECTORS: case KW_UV_VECTORS:
	case KW_FACE_INDICES: case KW_NORMAL_INDICES: case KW_UV_INDICES:
		return true;
	default:
		return false;
	}
}

static void sput(struct lexer *lx, size_t *len, char c)
{
	if (*len + 1 >= lx->scap) {
		lx->scap = lx->scap ? lx->scap * 2 : 256;
		lx->sbuf = realloc(lx->sbuf, lx->scap);
		if (!lx->sbuf) abort();
	}
	lx->sbuf[(*len)++] = c;
}

/* A string literal: "..." with backslash escapes. As in POV-Ray a string
 * may span lines (the line breaks are part of it); one that the file ends
 * inside is reported where it began, and so is one with more than 255
 * characters of source between its quotes (POV-Ray's "String too long":
 * 255 pass, 256 fail, an escape counting as the characters it is written
 * with; tests/errors/string-too-long). */
static bool lex_string(struct lexer *lx)
{
	enum { MAX_STRING = 255 };
	struct srcpos start = here(lx, lx->i);
	size_t len = 0;
	lx->i++; /* opening quote */
	size_t first = lx->i;
	for (;;) {
		if (lx->i >= lx->n) {
			diag_report(lx->d, DIAG_ERROR, start, "unterminated string: the file ends before its closing '\"'");
			return false;
		}
		if (lx->s[lx->i] == '\n')
			newline(lx, lx->i);
		char c = lx->s[lx->i++];
		if (c == '"')
			break;
		if (c == '\\' && lx->i < lx->n) {
			struct srcpos epos = here(lx, lx->i - 1);
			char e = lx->s[lx->i++];
			switch (e) {
			case 'a': c = '\a'; break;
			case 'b': c = '\b'; break;
			case 'f': c = '\f'; break;
			case 'n': c = '\n'; break;
			case 'r': c = '\r'; break;
			case 't': c = '\t'; break;
			case 'v': c = '\v'; break;
			case '0': c = '\0'; break;
			case '\\': c = '\\'; break;
			case '\'': c = '\''; break;
			case '"': c = '"'; break;
			case 'u': {
				/* \uNNNN: a character by its code, kept whatever the
				 * charset (ustr.h: ASCII is one byte, other codes the
				 * coded form). */
				unsigned code = 0;
				int k;
				for (k = 0; k < 4 && lx->i < lx->n && isxdigit((unsigned char)lx->s[lx->i]); k++) {
					char h = lx->s[lx->i++];
					code = code * 16 + (unsigned)(isdigit((unsigned char)h) ? h - '0' : (tolower((unsigned char)h) - 'a' + 10));
				}
				if (k != 4) {
					diag_report(lx->d, DIAG_ERROR, epos, "'\\u' needs four hexadecimal digits");
					return false;
				}
				if (code < 0x80) {
					c = (char)code;
				} else {
					char enc[4];
					ustr_put(enc, code);
					for (int j = 0; j < 3; j++)
						sput(lx, &len, enc[j]);
					c = enc[3];
				}
				break;
			}
			default:
				diag_report(lx->d, DIAG_ERROR, epos, "unknown escape sequence '\\%c' in string", e);
				return false;
			}
		} else if ((unsigned char)c == USTR_CODED) {
			/* A raw 0xFF would begin a coded character: it is the
			 * code 0xFF. */
			char enc[4];
			ustr_put(enc, 0xFF);
			for (int j = 0; j < 3; j++)
				sput(lx, &len, enc[j]);
			c = enc[3];
		}
		sput(lx, &len, c);
	}
	if (lx->i - 1 - first > MAX_STRING) {
		diag_report(lx->d, DIAG_ERROR, start, "string too long: POV-Ray allows at most %d characters between the quotes", MAX_STRING);
		return false;
	}
	struct token *t = push(lx, TOK_STRING, start);
	t->str = intern(lx->sm->names, lx->sbuf ? lx->sbuf : "", len);
	return true;
}

static bool lex_word(struct lexer *lx)
{
	size_t start = lx->i;
	while (lx->i < lx->n && (isalnum((unsigned char)lx->s[lx->i]) || lx->s[lx->i] == '_'))
		lx->i++;
	size_t len = lx->i - start;
	enum kw k = kw_lookup(lx->s + start, len);
	struct token *t = push(lx, k ? TOK_KEYWORD : TOK_IDENT, here(lx, start));
	if (k)
		t->kw = (uint16_t)k;
	else
		t->str = intern(lx->sm->names, lx->s + start, len);
	return true;
}

static bool lex_punct(struct lexer *lx)
{
	size_t start = lx->i;
	char c = lx->s[lx->i++];
	char d = lx->i < lx->n ? lx->s[lx->i] : 0;
	enum tok_kind k;
	switch (c) {
	case '{': k = TOK_LBRACE; break;
	case '}': k = TOK_RBRACE; break;
	case '(': k = TOK_LPAREN; break;
	case ')': k = TOK_RPAREN; break;
	case '[': k = TOK_LBRACKET; break;
	case ']': k = TOK_RBRACKET; break;
	case '+': k = TOK_PLUS; break;
	case '-': k = TOK_MINUS; break;
	case '*': k = TOK_STAR; break;
	case '/': k = TOK_SLASH; break;
	case ',': k = TOK_COMMA; break;
	case ';': k = TOK_SEMI; break;
	case '.': k = TOK_DOT; break;
	case ':': k = TOK_COLON; break;
	case '?': k = TOK_QUESTION; break;
	case '&': k = TOK_AMP; break;
	case '|': k = TOK_BAR; break;
	case '#': k = TOK_HASH; break;
	case '=': k = TOK_EQ; break;
	case '<':
		if (d == '=') { lx->i++; k = TOK_LE; } else k = TOK_LT;
		break;
	case '>':
		if (d == '=') { lx->i++; k = TOK_GE; } else k = TOK_GT;
		break;
	case '!':
		if (d == '=') { lx->i++; k = TOK_NE; } else k = TOK_BANG;
		break;
	default: {
		struct srcpos p = here(lx, start);
		if ((unsigned char)c >= 0x20 && (unsigned char)c < 0x7f)
			diag_report(lx->d, DIAG_ERROR, p, "unexpected character '%c'", c);
		else
			diag_report(lx->d, DIAG_ERROR, p, "unexpected byte 0x%02x", (unsigned char)c);
		return false;
	}
	}
	push(lx, k, here(lx, start));
	return true;
}

bool lex_file(struct srcmgr *sm, uint32_t file, struct diag *d)
{
	struct srcfile *f = sm->files[file];
	if (f->toks)
		return true;
	struct lexer lx = {.sm = sm, .d = d, .file = file, .s = f->text, .n = f->len, .line = 1};
	bool ok = true;
	/* Skip a UTF-8 byte order mark. */
	if (lx.n >= 3 && memcmp(lx.s, "\xef\xbb\xbf", 3) == 0)
		lx.i = lx.line_start = 3;
	for (;;) {
		if (!skip_space(&lx)) {
			ok = false;
			break;
		}
		if (lx.i >= lx.n)
			break;
		unsigned char c = (unsigned char)lx.s[lx.i];
		bool r;
		if (isdigit(c) || (c == '.' && lx.i + 1 < lx.n && isdigit((unsigned char)lx.s[lx.i + 1])))
			r = lex_number(&lx);
		else if (isalpha(c) || c == '_')
			r = lex_word(&lx);
		else if (c == '"')
			r = lex_string(&lx);
		else if (c == '<' && lx.in_list && starts_item(&lx) && lex_run(&lx))
			r = true;
		else {
			r = lex_punct(&lx);
			if (r && c == '{')
				lx.in_list = opens_list(&lx);
			else if (c == '}')
				lx.in_list = false;
		}
		if (!r) {
			ok = false;
			break;
		}
	}
	push(&lx, TOK_EOF, here(&lx, lx.i));
	free(lx.sbuf);
	f->toks = lx.toks;
	f->ntoks = lx.ntoks;
	f->blocks = lx.blocks;
	f->nblocks = lx.nblocks;
	return ok;
}

static const char *const kind_names[TOK__COUNT] = {
	[TOK_EOF] = "end of file", [TOK_IDENT] = "identifier", [TOK_KEYWORD] = "keyword",
	[TOK_NUMBER] = "number", [TOK_STRING] = "string", [TOK_HASH] = "#",
	[TOK_LBRACE] = "{", [TOK_RBRACE] = "}", [TOK_LPAREN] = "(", [TOK_RPAREN] = ")",
	[TOK_LBRACKET] = "[", [TOK_RBRACKET] = "]", [TOK_LT] = "<", [TOK_GT] = ">",
	[TOK_LE] = "<=", [TOK_GE] = ">=", [TOK_EQ] = "=", [TOK_NE] = "!=",
	[TOK_PLUS] = "+", [TOK_MINUS] = "-", [TOK_STAR] = "*", [TOK_SLASH] = "/",
	[TOK_COMMA] = ",", [TOK_SEMI] = ";", [TOK_DOT] = ".", [TOK_COLON] = ":",
	[TOK_QUESTION] = "?", [TOK_BANG] = "!", [TOK_AMP] = "&", [TOK_BAR] = "|",
	[TOK_NUMLIST] = "list of vectors",
};

const char *lex_kind_name(enum tok_kind k)
{
	return k < TOK__COUNT ? kind_names[k] : "?";
}

const char *lex_describe(const struct token *t, char *buf, size_t size)
{
	switch (t->kind) {
	case TOK_EOF: snprintf(buf, size, "end of file"); break;
	case TOK_IDENT: snprintf(buf, size, "identifier '%s'", t->str); break;
	case TOK_KEYWORD: snprintf(buf, size, "'%s'", kw_names[t->kw]); break;
	case TOK_NUMBER: snprintf(buf, size, "number %.10g", t->num); break;
	case TOK_STRING: snprintf(buf, size, "string \"%.40s\"", t->str); break;
	case TOK_NUMLIST: snprintf(buf, size, "a list of %u vectors", (unsigned)t->list->count); break;
	default: snprintf(buf, size, "'%s'", lex_kind_name((enum tok_kind)t->kind)); break;
	}
	return buf;
}

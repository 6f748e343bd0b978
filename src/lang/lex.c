/* lex.c: the hand-written lexer (see lex.h). */
#include "lang/lex.h"

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
static bool skip_space(struct lexer *lx)
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

static bool lex_number(struct lexer *lx)
{
	size_t start = lx->i;
	const char *s = lx->s;
	while (lx->i < lx->n && isdigit((unsigned char)s[lx->i]))
		lx->i++;
	if (lx->i < lx->n && s[lx->i] == '.') {
		lx->i++;
		while (lx->i < lx->n && isdigit((unsigned char)s[lx->i]))
			lx->i++;
	}
	if (lx->i < lx->n && (s[lx->i] == 'e' || s[lx->i] == 'E')) {
		size_t j = lx->i + 1;
		if (j < lx->n && (s[j] == '+' || s[j] == '-'))
			j++;
		if (j < lx->n && isdigit((unsigned char)s[j])) {
			while (j < lx->n && isdigit((unsigned char)s[j]))
				j++;
			lx->i = j;
		}
	}
	char buf[128];
	size_t len = lx->i - start;
	struct token *t = push(lx, TOK_NUMBER, here(lx, start));
	if (len >= sizeof buf) {
		char *tmp = malloc(len + 1);
		if (!tmp) abort();
		memcpy(tmp, s + start, len);
		tmp[len] = 0;
		t->num = strtod(tmp, NULL);
		free(tmp);
	} else {
		memcpy(buf, s + start, len);
		buf[len] = 0;
		t->num = strtod(buf, NULL);
	}
	return true;
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

/* A string literal: "..." with backslash escapes. Strings may not span
 * lines; an unterminated one is reported where it began. */
static bool lex_string(struct lexer *lx)
{
	struct srcpos start = here(lx, lx->i);
	size_t len = 0;
	lx->i++; /* opening quote */
	for (;;) {
		if (lx->i >= lx->n || lx->s[lx->i] == '\n') {
			diag_report(lx->d, DIAG_ERROR, start, "unterminated string: no closing '\"' on this line");
			return false;
		}
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
				/* \uNNNN: a character by its code; codes up to 255 are one
				 * byte (so asc() and strlen() count characters), others
				 * are written as UTF-8. */
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
				if (code < 256) {
					c = (char)code;
				} else {
					if (code < 0x800) {
						sput(lx, &len, (char)(0xc0 | (code >> 6)));
					} else {
						sput(lx, &len, (char)(0xe0 | (code >> 12)));
						sput(lx, &len, (char)(0x80 | ((code >> 6) & 0x3f)));
					}
					c = (char)(0x80 | (code & 0x3f));
				}
				break;
			}
			default:
				diag_report(lx->d, DIAG_ERROR, epos, "unknown escape sequence '\\%c' in string", e);
				return false;
			}
		}
		sput(lx, &len, c);
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
		else
			r = lex_punct(&lx);
		if (!r) {
			ok = false;
			break;
		}
	}
	push(&lx, TOK_EOF, here(&lx, lx.i));
	free(lx.sbuf);
	f->toks = lx.toks;
	f->ntoks = lx.ntoks;
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
	default: snprintf(buf, size, "'%s'", lex_kind_name((enum tok_kind)t->kind)); break;
	}
	return buf;
}

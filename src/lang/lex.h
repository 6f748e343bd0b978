/* lex.h: the lexer. A source file is turned into an array of tokens once;
 * includes, loops and macro calls replay ranges of that array and never
 * lex again. */
#ifndef LUCENT_LEX_H
#define LUCENT_LEX_H

#include "lang/diag.h"
#include "lang/kw.h"
#include "lang/source.h"

#include <stdbool.h>
#include <stdint.h>

enum tok_kind {
	TOK_EOF,
	TOK_IDENT,    /* an identifier: str is interned */
	TOK_KEYWORD,  /* a reserved word: kw */
	TOK_NUMBER,   /* num */
	TOK_STRING,   /* str: interned, escapes already applied */
	TOK_HASH,     /* '#', which starts a directive */
	TOK_LBRACE, TOK_RBRACE, TOK_LPAREN, TOK_RPAREN, TOK_LBRACKET, TOK_RBRACKET,
	TOK_LT, TOK_GT, TOK_LE, TOK_GE, TOK_EQ, TOK_NE, /* < > <= >= = != */
	TOK_PLUS, TOK_MINUS, TOK_STAR, TOK_SLASH,
	TOK_COMMA, TOK_SEMI, TOK_DOT, TOK_COLON, TOK_QUESTION,
	TOK_BANG, TOK_AMP, TOK_BAR,
	TOK_NUMLIST,  /* list: a run of literal vectors inside a mesh2 list */
	TOK__COUNT
};

/* A run of literal vectors `<n, n, n>` (all of 2 or all of 3 numbers,
 * commas between them optional) found inside the braces of a mesh2 list
 * (vertex_vectors, normal_vectors, uv_vectors, face_indices,
 * normal_indices, uv_indices). The lexer checks the run and keeps only
 * where it is, instead of 8 tokens per vector; the parser of those lists
 * reads the numbers from the text with lex_numlist_next. This is what
 * keeps a million-triangle mesh2 small and quick. Owned by the file. */
struct numlist {
	uint32_t count;      /* vectors */
	uint32_t dim;        /* numbers per vector: 2 or 3 */
	size_t start;        /* offset of the first '<' in the file's text */
	size_t line_start;   /* offset of the start of its line */
	uint32_t line;
};

struct token {
	uint8_t kind;     /* enum tok_kind */
	uint16_t kw;      /* enum kw, for TOK_KEYWORD */
	struct srcpos pos;
	union {
		double num;
		const char *str;
		const struct numlist *list;
	};
};

/* Lex file `file` of sm into sm's token array for it (no-op if already
 * lexed). On a lexical error, reports it through d and returns false; the
 * token array then ends with TOK_EOF at the error. */
bool lex_file(struct srcmgr *sm, uint32_t file, struct diag *d);

/* Reading a numlist's vectors in order. */
struct numlist_iter {
	const char *s;
	size_t n, i, line_start;
	uint32_t file, line;
};
void lex_numlist_begin(struct numlist_iter *it, const struct srcmgr *sm, uint32_t file, const struct numlist *l);
/* The next vector into v (dim numbers) and where its '<' is. */
void lex_numlist_next(struct numlist_iter *it, double v[3], struct srcpos *pos);

/* A printable description of a token for messages: "'sphere'", "number 3",
 * "end of file". Writes into buf and returns it. */
const char *lex_describe(const struct token *t, char *buf, size_t size);
/* The spelling of a punctuation kind ("{", "<=", ...). */
const char *lex_kind_name(enum tok_kind k);

#endif

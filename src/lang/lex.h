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
	TOK__COUNT
};

struct token {
	uint8_t kind;     /* enum tok_kind */
	uint16_t kw;      /* enum kw, for TOK_KEYWORD */
	struct srcpos pos;
	union {
		double num;
		const char *str;
	};
};

/* Lex file `file` of sm into sm's token array for it (no-op if already
 * lexed). On a lexical error, reports it through d and returns false; the
 * token array then ends with TOK_EOF at the error. */
bool lex_file(struct srcmgr *sm, uint32_t file, struct diag *d);

/* A printable description of a token for messages: "'sphere'", "number 3",
 * "end of file". Writes into buf and returns it. */
const char *lex_describe(const struct token *t, char *buf, size_t size);
/* The spelling of a punctuation kind ("{", "<=", ...). */
const char *lex_kind_name(enum tok_kind k);

#endif

/* test_lex.c: unit tests for the lexer (src/lang/lex.h) with the source
 * manager (src/lang/source.h) and diagnostics (src/lang/diag.h): token
 * kinds and values, string escapes and interning, comments, positions,
 * and the text of lexical error messages. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "lang/diag.h"
#include "lang/intern.h"
#include "lang/lex.h"
#include "lang/source.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One lexed text: the source manager, its diagnostics captured in memory,
 * and the outcome. */
struct lexed {
	struct srcmgr *sm;
	struct diag d;
	FILE *err;
	char *msg;       /* everything reported, once lex_text has returned */
	size_t msglen;
	uint32_t file;
	bool ok;
	const struct token *toks;
	size_t ntoks;
};

/* Lex `len` bytes of text as the file "t.pov". */
static void lex_bytes(struct lexed *lx, const char *text, size_t len)
{
	memset(lx, 0, sizeof *lx);
	lx->sm = src_new();
	char *copy = malloc(len + 1);
	assert_non_null(copy);
	memcpy(copy, text, len);
	copy[len] = 0;
	lx->file = src_add(lx->sm, "t.pov", copy, len);
	assert_int_equal(lx->file, 1);
	lx->err = open_memstream(&lx->msg, &lx->msglen);
	assert_non_null(lx->err);
	diag_init(&lx->d, lx->sm, lx->err);
	lx->ok = lex_file(lx->sm, lx->file, &lx->d);
	fflush(lx->err);
	lx->toks = lx->sm->files[lx->file]->toks;
	lx->ntoks = lx->sm->files[lx->file]->ntoks;
	assert_non_null(lx->toks);
	/* The array always ends with exactly one end of file. */
	assert_true(lx->ntoks >= 1);
	assert_int_equal(lx->toks[lx->ntoks - 1].kind, TOK_EOF);
	for (size_t i = 0; i + 1 < lx->ntoks; i++)
		assert_int_not_equal(lx->toks[i].kind, TOK_EOF);
}

static void lex_text(struct lexed *lx, const char *text)
{
	lex_bytes(lx, text, strlen(text));
}

static void lexed_free(struct lexed *lx)
{
	fclose(lx->err);
	free(lx->msg);
	src_free(lx->sm);
}

/* Lex text that must be clean: no errors, no messages. */
static void lex_ok(struct lexed *lx, const char *text)
{
	lex_text(lx, text);
	if (!lx->ok || lx->d.errors || lx->msglen)
		fail_msg("lexing \"%s\" failed: %s", text, lx->msg);
}

static void assert_contains(const char *hay, const char *needle)
{
	if (!hay || !strstr(hay, needle))
		fail_msg("expected \"%s\" in:\n%s", needle, hay ? hay : "(null)");
}

static void assert_pos(const struct token *t, uint32_t line, uint32_t col)
{
	assert_int_equal(t->pos.file, 1);
	if (t->pos.line != line || t->pos.col != col)
		fail_msg("token at %u:%u, expected %u:%u", t->pos.line, t->pos.col, line, col);
}

static void test_identifiers_and_keywords(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "Sphere sphere box _x1 a_B2 plane SPHERE sphere_ sphere2");
	assert_int_equal(lx.ntoks, 10);
	assert_int_equal(lx.toks[0].kind, TOK_IDENT);
	assert_string_equal(lx.toks[0].str, "Sphere");
	assert_int_equal(lx.toks[1].kind, TOK_KEYWORD);
	assert_int_equal(lx.toks[1].kw, KW_SPHERE);
	assert_int_equal(lx.toks[2].kind, TOK_KEYWORD);
	assert_int_equal(lx.toks[2].kw, KW_BOX);
	assert_int_equal(lx.toks[3].kind, TOK_IDENT);
	assert_string_equal(lx.toks[3].str, "_x1");
	assert_int_equal(lx.toks[4].kind, TOK_IDENT);
	assert_string_equal(lx.toks[4].str, "a_B2");
	assert_int_equal(lx.toks[5].kind, TOK_KEYWORD);
	assert_int_equal(lx.toks[5].kw, KW_PLANE);
	assert_int_equal(lx.toks[6].kind, TOK_IDENT);
	assert_string_equal(lx.toks[6].str, "SPHERE");
	/* A keyword followed by more word characters is an identifier. */
	assert_int_equal(lx.toks[7].kind, TOK_IDENT);
	assert_string_equal(lx.toks[7].str, "sphere_");
	assert_int_equal(lx.toks[8].kind, TOK_IDENT);
	assert_string_equal(lx.toks[8].str, "sphere2");
	lexed_free(&lx);
}

static void test_identifier_interning(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "foo bar foo Foo foo_ foo");
	assert_int_equal(lx.ntoks, 7);
	assert_ptr_equal(lx.toks[0].str, lx.toks[2].str);
	assert_ptr_equal(lx.toks[0].str, lx.toks[5].str);
	assert_ptr_not_equal(lx.toks[0].str, lx.toks[1].str);
	assert_ptr_not_equal(lx.toks[0].str, lx.toks[3].str);
	assert_ptr_not_equal(lx.toks[0].str, lx.toks[4].str);
	/* Interned strings are NUL-terminated copies, not pointers into the text. */
	assert_int_equal(strlen(lx.toks[0].str), 3);
	lexed_free(&lx);
}

static void test_numbers(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "1 1.5 .5 1e-3 2.e5 3E+2 0.25 007 12345678901234567890 1E2 4.5e+0");
	static const double want[] = {1, 1.5, 0.5, 1e-3, 2e5, 300, 0.25, 7, 12345678901234567890.0, 100, 4.5};
	size_t n = sizeof want / sizeof want[0];
	assert_int_equal(lx.ntoks, n + 1);
	for (size_t i = 0; i < n; i++) {
		assert_int_equal(lx.toks[i].kind, TOK_NUMBER);
		if (lx.toks[i].num != want[i])
			fail_msg("number %zu: %.17g, expected %.17g", i, lx.toks[i].num, want[i]);
	}
	lexed_free(&lx);
}

static void test_number_boundaries(void **state)
{
	(void)state;
	struct lexed lx;
	/* No sign in a number: "-2" is a minus and a 2. A bare "e" with no
	 * digits after it is not part of the number. "1.5.25" is 1.5 then .25. */
	lex_ok(&lx, "<1,-2> 3e x2 1.5.25 5.");
	static const struct { int kind; double num; } want[] = {
		{TOK_LT, 0}, {TOK_NUMBER, 1}, {TOK_COMMA, 0}, {TOK_MINUS, 0}, {TOK_NUMBER, 2}, {TOK_GT, 0},
		{TOK_NUMBER, 3}, {TOK_IDENT, 0}, {TOK_IDENT, 0}, {TOK_NUMBER, 1.5}, {TOK_NUMBER, 0.25},
		{TOK_NUMBER, 5}, {TOK_EOF, 0},
	};
	size_t n = sizeof want / sizeof want[0];
	assert_int_equal(lx.ntoks, n);
	for (size_t i = 0; i < n; i++) {
		if (lx.toks[i].kind != want[i].kind)
			fail_msg("token %zu: kind %d, expected %d", i, lx.toks[i].kind, want[i].kind);
		if (want[i].kind == TOK_NUMBER && lx.toks[i].num != want[i].num)
			fail_msg("token %zu: %.17g, expected %.17g", i, lx.toks[i].num, want[i].num);
	}
	assert_string_equal(lx.toks[7].str, "e");
	assert_string_equal(lx.toks[8].str, "x2");
	lexed_free(&lx);
}

static void test_strings(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "\"plain\" \"a\\nb\\tc\\\\d\\\"e\" \"\" \"it's\" \"x // y /* z\"");
	assert_int_equal(lx.ntoks, 6);
	for (int i = 0; i < 5; i++)
		assert_int_equal(lx.toks[i].kind, TOK_STRING);
	assert_string_equal(lx.toks[0].str, "plain");
	assert_string_equal(lx.toks[1].str, "a\nb\tc\\d\"e");
	assert_string_equal(lx.toks[2].str, "");
	assert_string_equal(lx.toks[3].str, "it's");
	/* Comment markers inside a string are text. */
	assert_string_equal(lx.toks[4].str, "x // y /* z");
	/* The string's position is its opening quote. */
	assert_pos(&lx.toks[0], 1, 1);
	assert_pos(&lx.toks[1], 1, 9);
	lexed_free(&lx);
}

static void test_string_interning(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "\"abc\" \"abd\" \"abc\"\n\"a\\tb\" \"a\tb\"");
	assert_int_equal(lx.ntoks, 6);
	assert_ptr_equal(lx.toks[0].str, lx.toks[2].str);
	assert_ptr_not_equal(lx.toks[0].str, lx.toks[1].str);
	/* Equal after escapes are applied: the same string. */
	assert_ptr_equal(lx.toks[3].str, lx.toks[4].str);
	lexed_free(&lx);
}

static void test_comments(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "a // line comment */ sphere\n"
	            "b /* block /* nested */ still in the comment */ c\n"
	            "/**/d/* x */e// at the end");
	assert_int_equal(lx.ntoks, 6);
	static const char *const names[] = {"a", "b", "c", "d", "e"};
	for (int i = 0; i < 5; i++) {
		assert_int_equal(lx.toks[i].kind, TOK_IDENT);
		assert_string_equal(lx.toks[i].str, names[i]);
	}
	assert_pos(&lx.toks[0], 1, 1);
	assert_pos(&lx.toks[1], 2, 1);
	assert_pos(&lx.toks[2], 2, 49);
	assert_pos(&lx.toks[3], 3, 5);
	assert_pos(&lx.toks[4], 3, 13);
	lexed_free(&lx);
	/* Only comments and space: just the end of file. */
	lex_ok(&lx, "  // nothing\n/* at /* all */ */\n\t\n");
	assert_int_equal(lx.ntoks, 1);
	assert_pos(&lx.toks[0], 4, 1);
	lexed_free(&lx);
	/* An empty file. */
	lex_ok(&lx, "");
	assert_int_equal(lx.ntoks, 1);
	assert_pos(&lx.toks[0], 1, 1);
	lexed_free(&lx);
}

static void test_operators(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "< <= > >= = != + - * / ( ) [ ] { } , ; . : ? ! & | #");
	static const int want[] = {
		TOK_LT, TOK_LE, TOK_GT, TOK_GE, TOK_EQ, TOK_NE, TOK_PLUS, TOK_MINUS, TOK_STAR,
		TOK_SLASH, TOK_LPAREN, TOK_RPAREN, TOK_LBRACKET, TOK_RBRACKET, TOK_LBRACE, TOK_RBRACE,
		TOK_COMMA, TOK_SEMI, TOK_DOT, TOK_COLON, TOK_QUESTION, TOK_BANG, TOK_AMP, TOK_BAR,
		TOK_HASH, TOK_EOF,
	};
	size_t n = sizeof want / sizeof want[0];
	assert_int_equal(lx.ntoks, n);
	for (size_t i = 0; i < n; i++) {
		if (lx.toks[i].kind != want[i])
			fail_msg("operator %zu: kind %d, expected %d", i, lx.toks[i].kind, want[i]);
		/* Each is two columns after the last, except after a two-byte one. */
	}
	assert_pos(&lx.toks[1], 1, 3);
	assert_pos(&lx.toks[2], 1, 6);
	assert_pos(&lx.toks[6], 1, 16);
	lexed_free(&lx);
	/* Without spaces: longest match, and '=' after '<' etc. only. */
	lex_ok(&lx, "<=>=!==<>a<-b!q#declare");
	static const int want2[] = {
		TOK_LE, TOK_GE, TOK_NE, TOK_EQ, TOK_LT, TOK_GT, TOK_IDENT, TOK_LT, TOK_MINUS, TOK_IDENT,
		TOK_BANG, TOK_IDENT, TOK_HASH, TOK_KEYWORD, TOK_EOF,
	};
	n = sizeof want2 / sizeof want2[0];
	assert_int_equal(lx.ntoks, n);
	for (size_t i = 0; i < n; i++)
		if (lx.toks[i].kind != want2[i])
			fail_msg("token %zu: kind %d, expected %d", i, lx.toks[i].kind, want2[i]);
	assert_int_equal(lx.toks[13].kw, KW_DECLARE);
	assert_pos(&lx.toks[3], 1, 7);
	assert_pos(&lx.toks[12], 1, 16);
	/* '/' that does not start a comment is a slash: "a/b". */
	lexed_free(&lx);
	lex_ok(&lx, "a/b");
	assert_int_equal(lx.ntoks, 4);
	assert_int_equal(lx.toks[1].kind, TOK_SLASH);
	lexed_free(&lx);
}

static void test_positions(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "a\n  bb\tc\n/* x\ny */ d\n\n   \"s\" 42\r\nz");
	assert_int_equal(lx.ntoks, 8);
	assert_pos(&lx.toks[0], 1, 1);
	assert_pos(&lx.toks[1], 2, 3);
	/* A tab is one byte. */
	assert_pos(&lx.toks[2], 2, 6);
	/* After a comment spanning lines, columns count from the new line. */
	assert_pos(&lx.toks[3], 4, 6);
	assert_pos(&lx.toks[4], 6, 4);
	assert_pos(&lx.toks[5], 6, 8);
	/* CRLF: the \r is white space, the next line starts after the \n. */
	assert_pos(&lx.toks[6], 7, 1);
	/* End of file sits just past the last byte. */
	assert_pos(&lx.toks[7], 7, 2);
	lexed_free(&lx);
	/* Columns count bytes, not characters: "é" is two bytes in UTF-8. */
	lex_ok(&lx, "\"\xc3\xa9\" x");
	assert_pos(&lx.toks[1], 1, 6);
	assert_string_equal(lx.toks[0].str, "\xc3\xa9");
	lexed_free(&lx);
	/* A UTF-8 byte order mark is skipped and does not count as columns. */
	lex_ok(&lx, "\xef\xbb\xbfsphere x");
	assert_int_equal(lx.ntoks, 3);
	assert_int_equal(lx.toks[0].kw, KW_SPHERE);
	assert_pos(&lx.toks[0], 1, 1);
	assert_pos(&lx.toks[1], 1, 8);
	lexed_free(&lx);
}

static void test_lex_twice(void **state)
{
	(void)state;
	struct lexed lx;
	lex_ok(&lx, "a b c");
	const struct token *first = lx.toks;
	/* A file already lexed is not lexed again. */
	assert_true(lex_file(lx.sm, lx.file, &lx.d));
	assert_ptr_equal(lx.sm->files[lx.file]->toks, first);
	assert_int_equal(lx.sm->files[lx.file]->ntoks, 4);
	lexed_free(&lx);
}

static void test_error_unterminated_comment(void **state)
{
	(void)state;
	struct lexed lx;
	lex_text(&lx, "a\n  /* /* inner */ still open\nmore\n");
	assert_false(lx.ok);
	assert_int_equal(lx.d.errors, 1);
	/* Reported where the comment began, not at the end of the file. */
	assert_contains(lx.msg, "t.pov:2:3: error: ");
	assert_contains(lx.msg, "unterminated comment");
	assert_contains(lx.msg, "    2 |   /* /* inner */ still open\n"
	                        "       |   ^\n");
	/* The tokens before the error are kept. */
	assert_int_equal(lx.ntoks, 2);
	assert_int_equal(lx.toks[0].kind, TOK_IDENT);
	lexed_free(&lx);
	/* Unclosed at the very start. */
	lex_text(&lx, "/*");
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:1:1: error: unterminated comment");
	lexed_free(&lx);
}

static void test_error_unterminated_string(void **state)
{
	(void)state;
	struct lexed lx;
	lex_text(&lx, "#declare S = \"abc\ny = 1;\n");
	assert_false(lx.ok);
	assert_int_equal(lx.d.errors, 1);
	assert_contains(lx.msg, "t.pov:1:14: error: ");
	assert_contains(lx.msg, "unterminated string");
	assert_contains(lx.msg, "    1 | #declare S = \"abc\n"
	                        "       |              ^\n");
	lexed_free(&lx);
	/* At the end of the file. */
	lex_text(&lx, "x\n  \"abc");
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:2:3: error: unterminated string");
	lexed_free(&lx);
	/* A backslash before the end of the file does not hide it. */
	lex_text(&lx, "\"abc\\");
	assert_false(lx.ok);
	assert_int_equal(lx.d.errors, 1);
	assert_contains(lx.msg, "t.pov:1:1: error: unterminated string");
	lexed_free(&lx);
}

static void test_error_bad_escape(void **state)
{
	(void)state;
	struct lexed lx;
	lex_text(&lx, "x \"ab\\qc\"");
	assert_false(lx.ok);
	assert_int_equal(lx.d.errors, 1);
	/* At the backslash. */
	assert_contains(lx.msg, "t.pov:1:6: error: ");
	assert_contains(lx.msg, "\\q");
	lexed_free(&lx);
}

static void test_error_unexpected_character(void **state)
{
	(void)state;
	struct lexed lx;
	lex_text(&lx, "sphere {\n  <0, 0, 0>, 1 @ pigment\n}\n");
	assert_false(lx.ok);
	assert_int_equal(lx.d.errors, 1);
	assert_contains(lx.msg, "t.pov:2:16: error: ");
	assert_contains(lx.msg, "'@'");
	assert_contains(lx.msg, "    2 |   <0, 0, 0>, 1 @ pigment\n"
	                        "       |                ^\n");
	/* Tokens up to the error survive, then the end of file. */
	assert_int_equal(lx.ntoks, 12);
	assert_int_equal(lx.toks[10].kind, TOK_NUMBER);
	lexed_free(&lx);

	lex_text(&lx, "a $b");
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:1:3: error: ");
	assert_contains(lx.msg, "'$'");
	lexed_free(&lx);

	/* A tab before the error stays a tab under the caret. */
	lex_text(&lx, "\tx `");
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:1:4: error: ");
	assert_contains(lx.msg, "    1 | \tx `\n"
	                        "       | \t  ^\n");
	lexed_free(&lx);

	/* A byte that is not printable ASCII is shown by its value. */
	lex_text(&lx, "x \x80");
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:1:3: error: ");
	assert_contains(lx.msg, "0x80");
	lexed_free(&lx);

	/* A NUL byte in the middle of the text. */
	lex_bytes(&lx, "ab\0c", 4);
	assert_false(lx.ok);
	assert_contains(lx.msg, "t.pov:1:3: error: ");
	assert_contains(lx.msg, "0x00");
	lexed_free(&lx);
}

static void test_describe(void **state)
{
	(void)state;
	struct lexed lx;
	char buf[64];
	lex_ok(&lx, "foo sphere 3 1.5 \"hi\" { <= # 1e300");
	assert_string_equal(lex_describe(&lx.toks[0], buf, sizeof buf), "identifier 'foo'");
	assert_string_equal(lex_describe(&lx.toks[1], buf, sizeof buf), "'sphere'");
	assert_string_equal(lex_describe(&lx.toks[2], buf, sizeof buf), "number 3");
	assert_string_equal(lex_describe(&lx.toks[3], buf, sizeof buf), "number 1.5");
	assert_string_equal(lex_describe(&lx.toks[4], buf, sizeof buf), "string \"hi\"");
	assert_string_equal(lex_describe(&lx.toks[5], buf, sizeof buf), "'{'");
	assert_string_equal(lex_describe(&lx.toks[6], buf, sizeof buf), "'<='");
	assert_string_equal(lex_describe(&lx.toks[7], buf, sizeof buf), "'#'");
	assert_string_equal(lex_describe(&lx.toks[8], buf, sizeof buf), "number 1e+300");
	assert_string_equal(lex_describe(&lx.toks[9], buf, sizeof buf), "end of file");
	/* The result is buf itself, truncated to fit. */
	char small[8];
	assert_ptr_equal(lex_describe(&lx.toks[0], small, sizeof small), small);
	assert_string_equal(small, "identif");
	lexed_free(&lx);
	/* Long strings are cut in the description. */
	lex_ok(&lx, "\"0123456789012345678901234567890123456789abcdef\"");
	char big[128];
	assert_string_equal(lex_describe(&lx.toks[0], big, sizeof big),
	                    "string \"0123456789012345678901234567890123456789\"");
	lexed_free(&lx);
	/* Kind names. */
	assert_string_equal(lex_kind_name(TOK_NE), "!=");
	assert_string_equal(lex_kind_name(TOK_LBRACKET), "[");
	assert_string_equal(lex_kind_name(TOK_EOF), "end of file");
	assert_string_equal(lex_kind_name(TOK__COUNT), "?");
}

static void test_diag_without_position(void **state)
{
	(void)state;
	struct srcmgr *sm = src_new();
	char *msg = NULL;
	size_t len = 0;
	FILE *err = open_memstream(&msg, &len);
	assert_non_null(err);
	struct diag d;
	diag_init(&d, sm, err);
	struct srcpos none = {0, 0, 0};
	diag_report(&d, DIAG_WARNING, none, "something %d", 42);
	fflush(err);
	assert_string_equal(msg, "lucent: warning: something 42\n");
	assert_int_equal(d.warnings, 1);
	assert_int_equal(d.errors, 0);
	fclose(err);
	free(msg);
	src_free(sm);
}

/* intern_rollback forgets exactly the strings interned since intern_mark:
 * those interned before keep their pointers and are found again, the
 * forgotten ones are new copies when interned again. `grow` interns enough
 * to make the table grow (and rehash) between the mark and the rollback. */
static void rollback_case(int grow)
{
	struct interner *in = intern_new();
	const char *before[300];
	char buf[32];
	for (int i = 0; i < 300; i++) {
		snprintf(buf, sizeof buf, "old%d", i);
		before[i] = intern_cstr(in, buf);
	}
	intern_mark(in);
	int n = grow ? 5000 : 100;
	for (int i = 0; i < n; i++) {
		snprintf(buf, sizeof buf, "new%d", i);
		intern_cstr(in, buf);
		assert_ptr_equal(intern_cstr(in, buf), intern_cstr(in, buf));
	}
	assert_ptr_equal(intern_cstr(in, "old7"), before[7]);
	intern_rollback(in);
	for (int i = 0; i < 300; i++) {
		snprintf(buf, sizeof buf, "old%d", i);
		assert_ptr_equal(intern_cstr(in, buf), before[i]);
	}
	/* Not marked any more: this stays, and a second rollback is a no-op. */
	const char *kept = intern_cstr(in, "new1");
	assert_string_equal(kept, "new1");
	intern_rollback(in);
	assert_ptr_equal(intern_cstr(in, "new1"), kept);
	intern_free(in);
}

static void test_intern_rollback(void **state)
{
	(void)state;
	rollback_case(0);
}

static void test_intern_rollback_after_growth(void **state)
{
	(void)state;
	rollback_case(1);
}

/* src_truncate drops the files registered last and keeps the others. */
static void test_src_truncate(void **state)
{
	(void)state;
	struct srcmgr *sm = src_new();
	uint32_t a = src_add(sm, "a.pov", strdup("a"), 1);
	uint32_t b = src_add(sm, "b.pov", strdup("b"), 1);
	src_truncate(sm, b);
	assert_int_equal(src_find(sm, "a.pov"), a);
	assert_int_equal(src_find(sm, "b.pov"), 0);
	assert_null(src_file(sm, b));
	assert_int_equal(src_add(sm, "c.pov", strdup("c"), 1), b);
	src_free(sm);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_identifiers_and_keywords),
		cmocka_unit_test(test_identifier_interning),
		cmocka_unit_test(test_numbers),
		cmocka_unit_test(test_number_boundaries),
		cmocka_unit_test(test_strings),
		cmocka_unit_test(test_string_interning),
		cmocka_unit_test(test_comments),
		cmocka_unit_test(test_operators),
		cmocka_unit_test(test_positions),
		cmocka_unit_test(test_lex_twice),
		cmocka_unit_test(test_error_unterminated_comment),
		cmocka_unit_test(test_error_unterminated_string),
		cmocka_unit_test(test_error_bad_escape),
		cmocka_unit_test(test_error_unexpected_character),
		cmocka_unit_test(test_describe),
		cmocka_unit_test(test_diag_without_position),
		cmocka_unit_test(test_intern_rollback),
		cmocka_unit_test(test_intern_rollback_after_growth),
		cmocka_unit_test(test_src_truncate),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

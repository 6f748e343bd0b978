/* source.h: the source manager. It owns every file the parser reads: its
 * text, where each line starts (for error quotes), and its token array,
 * made once and reused by every later #include of the same file. */
#ifndef LUCENT_SOURCE_H
#define LUCENT_SOURCE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct token;
struct interner;

/* A place in a source file: every token and scene record carries one. */
struct srcpos {
	uint32_t file; /* index into the source manager; 0 = none */
	uint32_t line; /* 1-based */
	uint32_t col;  /* 1-based, in bytes */
};

struct srcfile {
	char *path;          /* as opened (relative or absolute) */
	char *text;          /* the whole file, NUL-terminated */
	size_t len;
	size_t *lines;       /* byte offset of each line's start */
	size_t nlines;
	struct token *toks;  /* lexed tokens, ending with TOK_EOF; NULL until lexed */
	size_t ntoks;
	void **blocks;       /* the numlists of TOK_NUMLIST tokens (owned) */
	size_t nblocks;
	unsigned long writes; /* the parser's write count when loaded (parser.h) */
};

struct srcmgr {
	struct srcfile **files; /* files[0] is unused so that file 0 means none */
	size_t nfiles, cap;
	struct interner *names; /* identifiers and strings of every file */
};

struct srcmgr *src_new(void);
void src_free(struct srcmgr *sm);
/* Forget every file registered after the first `nfiles` (counting the
 * unused index 0), as if they had never been read: the fuzz harness keeps
 * the stdlib's files, lexed once, across inputs. */
void src_truncate(struct srcmgr *sm, size_t nfiles);
/* Register text read from `path` (takes ownership of text, which must be
 * NUL-terminated at text[len]). Returns the new file's index. */
uint32_t src_add(struct srcmgr *sm, const char *path, char *text, size_t len);
/* Read a whole file (or standard input for "-") and register it. Returns 0
 * and sets errno if it cannot be read. */
uint32_t src_load(struct srcmgr *sm, const char *path);
/* The file registered last under exactly this path (a file read again
 * is registered again), or 0. */
uint32_t src_find(const struct srcmgr *sm, const char *path);
const struct srcfile *src_file(const struct srcmgr *sm, uint32_t file);
/* The text of line `line` of `file` (without its newline) and its length. */
const char *src_line(const struct srcmgr *sm, uint32_t file, uint32_t line, size_t *len);

#endif

/* intern.h: string interning. Every identifier and string the lexer makes
 * is stored once; two interned strings are equal exactly when their
 * pointers are, so name lookup compares pointers. */
#ifndef LUCENT_INTERN_H
#define LUCENT_INTERN_H

#include <stddef.h>

struct interner;

struct interner *intern_new(void);
void intern_free(struct interner *in);
/* Return the unique copy of s[0..n). The copy lives until intern_free and
 * is NUL-terminated. */
const char *intern(struct interner *in, const char *s, size_t n);
const char *intern_cstr(struct interner *in, const char *s);
/* Remember the strings interned from now on; intern_rollback frees them
 * and forgets them, as if they had never been interned (every pointer to
 * them becomes invalid). The fuzz harness keeps the stdlib's files lexed
 * across inputs and drops each input's own names after it. */
void intern_mark(struct interner *in);
void intern_rollback(struct interner *in);

#endif

/* sym.h: symbol tables. Names are interned, so lookup hashes and compares
 * pointers. Scopes form a stack: the global table at the bottom, then one
 * per include file and macro call (for #local), as the manual describes. */
#ifndef LUCENT_SYM_H
#define LUCENT_SYM_H

#include "lang/value.h"

#include <stddef.h>

struct symtab;

struct symtab *sym_new(void);
void sym_free(struct symtab *t);
/* Bump *gen whenever a binding is added to or removed from t, so that
 * whoever holds pointers to its values knows when they may have moved. */
void sym_track(struct symtab *t, unsigned long *gen);
/* The value bound to name in t, or NULL. */
struct value *sym_get(const struct symtab *t, const char *name);
/* Bind name to v in t, taking ownership of v (any old value is cleared). */
void sym_set(struct symtab *t, const char *name, struct value v);
/* Remove name from t; returns false if it was not there. */
bool sym_remove(struct symtab *t, const char *name);
/* Call fn for each bound name (order unspecified). */
void sym_each(const struct symtab *t, void (*fn)(void *arg, const char *name), void *arg);

#endif

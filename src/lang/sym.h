/* sym.h: symbol tables. Names are interned, so lookup hashes and compares
 * pointers. Scopes form a stack: the global table at the bottom, then one
 * per include file and macro call (for #local), as the manual describes. */
#ifndef LUCENT_SYM_H
#define LUCENT_SYM_H

#include "lang/value.h"

#include <stddef.h>
#include <stdint.h>

struct symtab;

/* Generations that tell a cached name lookup whether it still stands
 * (sym_track): name[sym_gen_bucket(N)] moves when a binding of N (or of a
 * name sharing its bucket) is added or removed, or enters or leaves the
 * scope chain (sym_touch, and a table's release); every bucket moves when
 * bindings may have moved in memory (a table grew, or a large one was
 * released). A lookup of N through the same scope chain finds the same
 * binding while its bucket's generation holds. */
#define SYM_GEN_BUCKETS 256
struct sym_gen {
	unsigned long name[SYM_GEN_BUCKETS];
};
static inline unsigned sym_gen_bucket(const char *name)
{
	uintptr_t x = (uintptr_t)name;
	return (unsigned)((x ^ (x >> 9)) >> 3) & (SYM_GEN_BUCKETS - 1);
}

struct symtab *sym_new(void);
/* Free t and its values; a tracked table moves the generations of the
 * names it held (its bindings are gone). */
void sym_free(struct symtab *t);
/* Remove every binding of t (as sym_free would), leaving it empty for
 * reuse. */
void sym_clear(struct symtab *t);
/* Bump *gen whenever a binding is added to or removed from t, so that
 * whoever holds pointers to its values knows when they may have moved;
 * and keep *ng as sym_gen describes (ng may be NULL). */
void sym_track(struct symtab *t, unsigned long *gen, struct sym_gen *ng);
/* Move the generations of every name bound in t (t's bindings now shadow
 * others of the same names: a macro's parameters when its frame is
 * entered). */
void sym_touch(const struct symtab *t);
/* The value bound to name in t, or NULL. */
struct value *sym_get(const struct symtab *t, const char *name);
/* Bind name to v in t, taking ownership of v (any old value is cleared). */
void sym_set(struct symtab *t, const char *name, struct value v);
/* Remove name from t; returns false if it was not there. */
bool sym_remove(struct symtab *t, const char *name);
/* Call fn for each bound name (order unspecified). */
void sym_each(const struct symtab *t, void (*fn)(void *arg, const char *name), void *arg);

#endif

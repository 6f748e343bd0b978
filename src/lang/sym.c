/* sym.c: symbol tables as open-addressing hash maps keyed by interned
 * name pointers (see sym.h). */
#include "lang/sym.h"

#include <stdint.h>
#include <stdlib.h>

struct entry {
	const char *name; /* NULL: empty; TOMBSTONE: removed */
	struct value val;
};

struct symtab {
	struct entry *e;
	size_t cap, used; /* used counts live entries and tombstones */
	unsigned long *gen; /* bumped when a binding is added or removed (sym_track) */
};

static const char tombstone[1];
#define TOMBSTONE (&tombstone[0])

static size_t hash_ptr(const char *p)
{
	uint64_t x = (uint64_t)(uintptr_t)p;
	x ^= x >> 33;
	x *= 0xff51afd7ed558ccdull;
	x ^= x >> 33;
	return (size_t)x;
}

struct symtab *sym_new(void)
{
	struct symtab *t = calloc(1, sizeof *t);
	if (!t) abort();
	t->cap = 8; /* most tables are a macro call's few parameters */
	t->e = calloc(t->cap, sizeof *t->e);
	if (!t->e) abort();
	return t;
}

void sym_track(struct symtab *t, unsigned long *gen)
{
	t->gen = gen;
}

void sym_free(struct symtab *t)
{
	if (!t) return;
	for (size_t i = 0; i < t->cap; i++)
		if (t->e[i].name && t->e[i].name != TOMBSTONE)
			val_clear(&t->e[i].val);
	free(t->e);
	free(t);
}

static struct entry *find(const struct symtab *t, const char *name)
{
	size_t i = hash_ptr(name) & (t->cap - 1);
	while (t->e[i].name) {
		if (t->e[i].name == name)
			return &t->e[i];
		i = (i + 1) & (t->cap - 1);
	}
	return NULL;
}

struct value *sym_get(const struct symtab *t, const char *name)
{
	struct entry *e = find(t, name);
	return e ? &e->val : NULL;
}

static void rehash(struct symtab *t, size_t ncap)
{
	struct entry *old = t->e;
	size_t ocap = t->cap;
	t->e = calloc(ncap, sizeof *t->e);
	if (!t->e) abort();
	t->cap = ncap;
	t->used = 0;
	for (size_t i = 0; i < ocap; i++)
		if (old[i].name && old[i].name != TOMBSTONE) {
			size_t j = hash_ptr(old[i].name) & (ncap - 1);
			while (t->e[j].name)
				j = (j + 1) & (ncap - 1);
			t->e[j] = old[i];
			t->used++;
		}
	free(old);
}

void sym_set(struct symtab *t, const char *name, struct value v)
{
	struct entry *e = find(t, name);
	if (e) {
		val_clear(&e->val);
		e->val = v;
		return;
	}
	if (t->gen)
		++*t->gen;
	if ((t->used + 1) * 4 >= t->cap * 3)
		rehash(t, t->cap * 2);
	size_t i = hash_ptr(name) & (t->cap - 1);
	while (t->e[i].name && t->e[i].name != TOMBSTONE)
		i = (i + 1) & (t->cap - 1);
	if (!t->e[i].name)
		t->used++;
	t->e[i].name = name;
	t->e[i].val = v;
}

bool sym_remove(struct symtab *t, const char *name)
{
	struct entry *e = find(t, name);
	if (!e)
		return false;
	val_clear(&e->val);
	e->name = TOMBSTONE;
	if (t->gen)
		++*t->gen;
	return true;
}

void sym_each(const struct symtab *t, void (*fn)(void *arg, const char *name), void *arg)
{
	for (size_t i = 0; i < t->cap; i++)
		if (t->e[i].name && t->e[i].name != TOMBSTONE)
			fn(arg, t->e[i].name);
}

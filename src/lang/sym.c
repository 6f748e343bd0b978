/* sym.c: symbol tables as open-addressing hash maps keyed by interned
 * name pointers (see sym.h). */
#include "lang/sym.h"

#include <stdint.h>
#include <stdlib.h>

struct entry {
	const char *name; /* NULL: empty; TOMBSTONE: removed */
	struct value val;
};

/* Most tables are a macro call's few parameters: their first entries live
 * in the table itself, so a call costs one allocation. */
#define SYM_SMALL 8

struct symtab {
	struct entry *e;    /* small, or a larger array of its own */
	size_t cap, used;   /* used counts live entries and tombstones */
	unsigned long *gen; /* bumped when a binding is added or removed (sym_track) */
	struct sym_gen *ng; /* kept as sym_gen describes (sym_track), or NULL */
	struct entry small[SYM_SMALL];
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

/* Move every bucket's generation (rare: a table grew or a large one went). */
static void bump_all(struct symtab *t)
{
	if (t->ng)
		for (size_t i = 0; i < SYM_GEN_BUCKETS; i++)
			t->ng->name[i]++;
}

struct symtab *sym_new(void)
{
	/* Only the names need clearing: an entry's value is written with it. */
	struct symtab *t = malloc(sizeof *t);
	if (!t) abort();
	t->e = t->small;
	t->cap = SYM_SMALL;
	t->used = 0;
	t->gen = NULL;
	t->ng = NULL;
	for (size_t i = 0; i < SYM_SMALL; i++)
		t->small[i].name = NULL;
	return t;
}

void sym_track(struct symtab *t, unsigned long *gen, struct sym_gen *ng)
{
	t->gen = gen;
	t->ng = ng;
}

void sym_touch(const struct symtab *t)
{
	if (!t->ng)
		return;
	for (size_t i = 0; i < t->cap; i++)
		if (t->e[i].name && t->e[i].name != TOMBSTONE)
			t->ng->name[sym_gen_bucket(t->e[i].name)]++;
}

/* Release t's bindings: their values, and the lookups cached on them
 * (sym_gen). */
static void release(struct symtab *t)
{
	/* A large table's names would take longer to list than every cached
	 * lookup takes to redo. */
	bool large = t->used > SYM_GEN_BUCKETS / 4;
	if (large)
		bump_all(t);
	for (size_t i = 0; i < t->cap; i++) {
		const char *name = t->e[i].name;
		if (name && name != TOMBSTONE) {
			if (t->ng && !large)
				t->ng->name[sym_gen_bucket(name)]++;
			val_clear(&t->e[i].val);
		}
	}
}

void sym_clear(struct symtab *t)
{
	release(t);
	if (t->e != t->small)
		free(t->e);
	t->e = t->small;
	t->cap = SYM_SMALL;
	t->used = 0;
	for (size_t i = 0; i < SYM_SMALL; i++)
		t->small[i].name = NULL;
}

void sym_free(struct symtab *t)
{
	if (!t) return;
	release(t);
	if (t->e != t->small)
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
	if (old != t->small)
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
	if (t->ng)
		t->ng->name[sym_gen_bucket(name)]++;
	if ((t->used + 1) * 4 >= t->cap * 3) {
		rehash(t, t->cap * 2);
		bump_all(t); /* every binding moved */
	}
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
	if (t->ng)
		t->ng->name[sym_gen_bucket(name)]++;
	return true;
}

void sym_each(const struct symtab *t, void (*fn)(void *arg, const char *name), void *arg)
{
	for (size_t i = 0; i < t->cap; i++)
		if (t->e[i].name && t->e[i].name != TOMBSTONE)
			fn(arg, t->e[i].name);
}

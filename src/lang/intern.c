/* intern.c: string interning with an open-addressing hash table. */
#include "lang/intern.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct interner {
	char **slots;   /* each entry: a string; its length precedes it as size_t */
	size_t cap;     /* power of two */
	size_t count;
	bool marked;    /* intern_mark: strings added since are logged */
	size_t mark_cap;
	char **log;     /* the strings added since the mark, in order */
	size_t nlog, caplog;
};

static uint64_t fnv1a(const char *s, size_t n)
{
	uint64_t h = 1469598103934665603ull;
	for (size_t i = 0; i < n; i++) {
		h ^= (unsigned char)s[i];
		h *= 1099511628211ull;
	}
	return h;
}

static size_t stored_len(const char *s) { return ((const size_t *)s)[-1]; }

struct interner *intern_new(void)
{
	struct interner *in = calloc(1, sizeof *in);
	if (!in) abort();
	in->cap = 1024;
	in->slots = calloc(in->cap, sizeof *in->slots);
	if (!in->slots) abort();
	return in;
}

void intern_free(struct interner *in)
{
	if (!in) return;
	for (size_t i = 0; i < in->cap; i++)
		if (in->slots[i])
			free(in->slots[i] - sizeof(size_t));
	free(in->slots);
	free(in->log);
	free(in);
}

static void grow(struct interner *in)
{
	size_t ncap = in->cap * 2;
	char **ns = calloc(ncap, sizeof *ns);
	if (!ns) abort();
	for (size_t i = 0; i < in->cap; i++) {
		char *s = in->slots[i];
		if (!s) continue;
		size_t j = fnv1a(s, stored_len(s)) & (ncap - 1);
		while (ns[j]) j = (j + 1) & (ncap - 1);
		ns[j] = s;
	}
	free(in->slots);
	in->slots = ns;
	in->cap = ncap;
}

const char *intern(struct interner *in, const char *s, size_t n)
{
	if (in->count * 2 >= in->cap)
		grow(in);
	size_t j = fnv1a(s, n) & (in->cap - 1);
	while (in->slots[j]) {
		char *e = in->slots[j];
		if (stored_len(e) == n && memcmp(e, s, n) == 0)
			return e;
		j = (j + 1) & (in->cap - 1);
	}
	char *block = malloc(sizeof(size_t) + n + 1);
	if (!block) abort();
	memcpy(block, &n, sizeof n);
	char *e = block + sizeof(size_t);
	memcpy(e, s, n);
	e[n] = 0;
	in->slots[j] = e;
	in->count++;
	if (in->marked) {
		if (in->nlog == in->caplog) {
			in->caplog = in->caplog ? in->caplog * 2 : 256;
			in->log = realloc(in->log, in->caplog * sizeof *in->log);
			if (!in->log) abort();
		}
		in->log[in->nlog++] = e;
	}
	return e;
}

void intern_mark(struct interner *in)
{
	in->marked = true;
	in->mark_cap = in->cap;
	in->nlog = 0;
}

static int cmp_ptr(const void *a, const void *b)
{
	const char *x = *(char *const *)a, *y = *(char *const *)b;
	return x < y ? -1 : x > y;
}

void intern_rollback(struct interner *in)
{
	if (!in->marked)
		return;
	in->marked = false;
	if (in->cap == in->mark_cap) {
		/* Removing the strings latest first undoes each insertion exactly:
		 * no string still present probed past a slot emptied here (it was
		 * empty when that string went in), so no tombstones are needed. */
		for (size_t k = in->nlog; k-- > 0;) {
			char *e = in->log[k];
			size_t j = fnv1a(e, stored_len(e)) & (in->cap - 1);
			while (in->slots[j] != e)
				j = (j + 1) & (in->cap - 1);
			in->slots[j] = NULL;
			free(e - sizeof(size_t));
		}
	} else {
		/* The table grew (and was rehashed) since the mark: drop the
		 * logged strings and place the others again. */
		qsort(in->log, in->nlog, sizeof *in->log, cmp_ptr);
		char **old = in->slots;
		in->slots = calloc(in->cap, sizeof *in->slots);
		if (!in->slots) abort();
		for (size_t i = 0; i < in->cap; i++) {
			char *e = old[i];
			if (!e || bsearch(&e, in->log, in->nlog, sizeof *in->log, cmp_ptr))
				continue;
			size_t j = fnv1a(e, stored_len(e)) & (in->cap - 1);
			while (in->slots[j]) j = (j + 1) & (in->cap - 1);
			in->slots[j] = e;
		}
		free(old);
		for (size_t k = 0; k < in->nlog; k++)
			free(in->log[k] - sizeof(size_t));
	}
	in->count -= in->nlog;
	in->nlog = 0;
}

const char *intern_cstr(struct interner *in, const char *s) { return intern(in, s, strlen(s)); }

/* intern.c: string interning with an open-addressing hash table. */
#include "lang/intern.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

struct interner {
	char **slots;   /* each entry: a string; its length precedes it as size_t */
	size_t cap;     /* power of two */
	size_t count;
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
	return e;
}

const char *intern_cstr(struct interner *in, const char *s) { return intern(in, s, strlen(s)); }

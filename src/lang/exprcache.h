/* exprcache.h: float expressions compiled once per place in the source
 * and run from then on without reading their tokens (see exprcache.c). */
#ifndef LUCENT_EXPRCACHE_H
#define LUCENT_EXPRCACHE_H

#include "lang/value.h"

#include <stdbool.h>

struct parser;
struct token;
struct exprcache;

/* What exprcache_try hands the ordinary parse to report on. */
struct exprcache_ticket {
	const struct token *key;     /* NULL: nothing to record */
	const struct token *toks;    /* the frame's tokens */
	size_t limit;                /* the frame's end */
	int frame;
	unsigned long events;
	bool rel_ok;
	bool operand;
};

struct exprcache *exprcache_new(void);
void exprcache_free(struct exprcache *c);

/* Evaluate the expression at the parser's position from its compiled
 * form: true with the value in *out and the parser past the expression,
 * or false, leaving the parser as it was, when the ordinary parser must
 * read it; then call exprcache_record with tk and its result. */
bool exprcache_try(struct parser *p, struct value *out, struct exprcache_ticket *tk);
/* The same for an operand without `? :` at its top (what parse_binary
 * reads: a colour after `color`). Kept apart from exprcache_try's
 * entries, which may take in a `? :` that follows. */
bool exprcache_try_operand(struct parser *p, struct value *out, struct exprcache_ticket *tk);
/* The same for a caller that wants a float (any other result: false). */
bool exprcache_try_float(struct parser *p, double *out, struct exprcache_ticket *tk);
void exprcache_record(struct parser *p, const struct exprcache_ticket *tk, const struct value *v);

#endif

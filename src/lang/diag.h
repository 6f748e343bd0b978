/* diag.h: diagnostics. A message reads
 *   file:line:col: error: what went wrong
 * then quotes the source line with a caret under the column, then the chain
 * of includes and macro calls that led there (supplied by the parser
 * through a callback). */
#ifndef LUCENT_DIAG_H
#define LUCENT_DIAG_H

#include "lang/source.h"

#include <stdarg.h>
#include <stdio.h>

enum diag_level { DIAG_ERROR, DIAG_WARNING, DIAG_NOTE };

struct diag {
	const struct srcmgr *src;
	FILE *out;           /* where messages go (stderr) */
	int errors, warnings;
	/* Prints "  in file included from ..." lines for the current parse
	 * state; may be NULL. */
	void (*context)(void *ctx, FILE *out);
	void *context_arg;
};

void diag_init(struct diag *d, const struct srcmgr *src, FILE *out);
/* Report at pos (pos.file == 0: no position, just "lucent: error: ..."). */
void diag_report(struct diag *d, enum diag_level lvl, struct srcpos pos, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
void diag_vreport(struct diag *d, enum diag_level lvl, struct srcpos pos, const char *fmt, va_list ap);

#endif

/* diag.c: diagnostics with a quoted source line and a caret. */
#include <stdarg.h>

#include "lang/diag.h"

static const char *const level_names[] = {"error", "warning", "note"};

void diag_init(struct diag *d, const struct srcmgr *src, FILE *out)
{
	d->src = src;
	d->out = out;
	d->errors = d->warnings = 0;
	d->context = NULL;
	d->context_arg = NULL;
}

void diag_vreport(struct diag *d, enum diag_level lvl, struct srcpos pos, const char *fmt, va_list ap)
{
	const struct srcfile *f = d->src ? src_file(d->src, pos.file) : NULL;
	if (lvl == DIAG_ERROR) d->errors++;
	if (lvl == DIAG_WARNING) d->warnings++;
	if (f)
		fprintf(d->out, "%s:%u:%u: %s: ", f->path, pos.line, pos.col, level_names[lvl]);
	else
		fprintf(d->out, "lucent: %s: ", level_names[lvl]);
	vfprintf(d->out, fmt, ap);
	fputc('\n', d->out);
	if (f && pos.line > 0) {
		size_t n;
		const char *line = src_line(d->src, pos.file, pos.line, &n);
		fprintf(d->out, " %5u | %.*s\n       | ", pos.line, (int)n, line);
		/* Tabs in the quoted line stay tabs under the caret so it lines up. */
		for (size_t i = 0; i + 1 < pos.col && i < n; i++)
			fputc(line[i] == '\t' ? '\t' : ' ', d->out);
		fputs("^\n", d->out);
	}
	if (d->context && lvl != DIAG_NOTE)
		d->context(d->context_arg, d->out);
	fflush(d->out);
}

void diag_report(struct diag *d, enum diag_level lvl, struct srcpos pos, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vreport(d, lvl, pos, fmt, ap);
	va_end(ap);
}

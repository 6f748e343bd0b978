/* source.c: the source manager (see source.h). */
#include "lang/source.h"

#include "lang/intern.h"
#include "lang/lex.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct srcmgr *src_new(void)
{
	struct srcmgr *sm = calloc(1, sizeof *sm);
	if (!sm) abort();
	sm->cap = 8;
	sm->files = calloc(sm->cap, sizeof *sm->files);
	if (!sm->files) abort();
	sm->nfiles = 1;
	sm->names = intern_new();
	return sm;
}

void src_truncate(struct srcmgr *sm, size_t nfiles)
{
	while (sm->nfiles > nfiles && sm->nfiles > 1) {
		struct srcfile *f = sm->files[--sm->nfiles];
		free(f->path);
		free(f->text);
		free(f->lines);
		free(f->toks);
		for (size_t b = 0; b < f->nblocks; b++)
			free(f->blocks[b]);
		free(f->blocks);
		free(f);
	}
}

void src_free(struct srcmgr *sm)
{
	if (!sm) return;
	src_truncate(sm, 1);
	free(sm->files);
	intern_free(sm->names);
	free(sm);
}

uint32_t src_add(struct srcmgr *sm, const char *path, char *text, size_t len)
{
	if (sm->nfiles == sm->cap) {
		sm->cap *= 2;
		sm->files = realloc(sm->files, sm->cap * sizeof *sm->files);
		if (!sm->files) abort();
	}
	struct srcfile *f = calloc(1, sizeof *f);
	if (!f) abort();
	f->path = strdup(path);
	f->text = text;
	f->len = len;
	size_t cap = 64;
	f->lines = malloc(cap * sizeof *f->lines);
	if (!f->path || !f->lines) abort();
	f->lines[f->nlines++] = 0;
	/* memchr finds the line ends many bytes at a time. */
	for (const char *q = text, *end = text + len; q < end && (q = memchr(q, '\n', (size_t)(end - q))); q++) {
		if (f->nlines == cap) {
			cap *= 2;
			f->lines = realloc(f->lines, cap * sizeof *f->lines);
			if (!f->lines) abort();
		}
		f->lines[f->nlines++] = (size_t)(q - text) + 1;
	}
	sm->files[sm->nfiles] = f;
	return (uint32_t)sm->nfiles++;
}

uint32_t src_load(struct srcmgr *sm, const char *path)
{
	FILE *fp = strcmp(path, "-") == 0 ? stdin : fopen(path, "rb");
	if (!fp)
		return 0;
	size_t cap = 1 << 16, len = 0;
	char *buf = malloc(cap);
	if (!buf) abort();
	for (;;) {
		if (len + 1 >= cap) {
			cap *= 2;
			buf = realloc(buf, cap);
			if (!buf) abort();
		}
		size_t n = fread(buf + len, 1, cap - len - 1, fp);
		len += n;
		if (n == 0)
			break;
	}
	int err = ferror(fp) ? EIO : 0;
	if (fp != stdin)
		fclose(fp);
	if (err) {
		free(buf);
		errno = err;
		return 0;
	}
	buf[len] = 0;
	return src_add(sm, path, buf, len);
}

uint32_t src_find(const struct srcmgr *sm, const char *path)
{
	for (size_t i = sm->nfiles - 1; i >= 1; i--)
		if (strcmp(sm->files[i]->path, path) == 0)
			return (uint32_t)i;
	return 0;
}

const struct srcfile *src_file(const struct srcmgr *sm, uint32_t file)
{
	return file > 0 && file < sm->nfiles ? sm->files[file] : NULL;
}

const char *src_line(const struct srcmgr *sm, uint32_t file, uint32_t line, size_t *len)
{
	const struct srcfile *f = src_file(sm, file);
	if (!f || line == 0 || line > f->nlines) {
		*len = 0;
		return "";
	}
	size_t start = f->lines[line - 1];
	size_t end = line < f->nlines ? f->lines[line] - 1 : f->len;
	if (end > start && f->text[end - 1] == '\r')
		end--;
	*len = end - start;
	return f->text + start;
}

/* parsetext.h: parse a scene given as text, for the unit tests that check
 * what the parser builds. Include after <cmocka.h>. */
#ifndef LUCENT_PARSETEXT_H
#define LUCENT_PARSETEXT_H

#include "lang/diag.h"
#include "lang/parse.h"
#include "lang/source.h"
#include "scene/scene.h"

#include <stdio.h>
#include <unistd.h>

struct parsed {
	struct srcmgr *sm;
	struct scene *s;
	char path[64];
};

/* Parse the scene text; fails the test on a parse error. */
static inline void parse_text(struct parsed *r, const char *text)
{
	snprintf(r->path, sizeof r->path, "/tmp/lucent-test-parse-%d.pov", (int)getpid());
	FILE *f = fopen(r->path, "w");
	assert_non_null(f);
	fputs(text, f);
	fclose(f);
	r->sm = src_new();
	struct diag d;
	diag_init(&d, r->sm, stderr);
	r->s = scene_new();
	struct parse_opts o = {.input = r->path, .image_width = 8, .image_height = 8, .debug_out = stderr};
	assert_int_equal(parse_scene(r->sm, &d, &o, r->s), 0);
}

static inline void parsed_free(struct parsed *r)
{
	scene_free(r->s);
	src_free(r->sm);
	remove(r->path);
}

#endif

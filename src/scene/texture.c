/* texture.c: textures, pigments and finishes (see texture.h). */
#include "scene/texture.h"

#include <stdlib.h>

struct finish finish_default(void)
{
	struct finish f = {
		.ambient = {0.1, 0.1, 0.1},
		.diffuse = 0.6,
		.brilliance = 1.0,
		.phong = 0.0,
		.phong_size = 40.0,
		.specular = 0.0,
		.roughness = 0.05,
	};
	return f;
}

struct texture *texture_new(void)
{
	struct texture *t = calloc(1, sizeof *t);
	if (!t) abort();
	t->refs = 1;
	t->pigment.kind = PIGMENT_SOLID;
	t->finish = finish_default();
	return t;
}

struct texture *texture_ref(struct texture *t)
{
	if (t)
		t->refs++;
	return t;
}

void texture_unref(struct texture *t)
{
	if (t && --t->refs == 0)
		free(t);
}

struct texture *texture_copy(const struct texture *t)
{
	struct texture *c = malloc(sizeof *c);
	if (!c) abort();
	*c = *t;
	c->refs = 1;
	return c;
}

/* atmos.c: the atmosphere's storage and POV-Ray's defaults (see atmos.h). */
#include "scene/atmos.h"

#include "scene/texture.h"

#include <stdlib.h>

struct fog fog_default(void)
{
	struct fog f = {0};
	f.type = FOG_CONSTANT;
	f.up = v3(0, 1, 0);
	f.turb = (struct turbulence){v3(0, 0, 0), 6, 0.5, 2.0};
	f.turb_depth = 0.5;
	return f;
}

struct rainbow rainbow_default(void)
{
	struct rainbow r = {0};
	r.up = v3(0, 1, 0);
	r.arc_angle = 360;
	r.falloff_angle = 360;
	return r;
}

struct sky_sphere *sky_sphere_new(void)
{
	struct sky_sphere *s = calloc(1, sizeof *s);
	if (!s) abort();
	s->xf = xform_identity();
	s->emission = rgb_make(1, 1, 1);
	return s;
}

void sky_sphere_add(struct sky_sphere *s, struct pigment *pg)
{
	struct pigment **v = realloc(s->pigments, (s->npigments + 1) * sizeof *v);
	if (!v) abort();
	s->pigments = v;
	s->pigments[s->npigments++] = pg;
}

struct sky_sphere *sky_sphere_copy(const struct sky_sphere *s)
{
	struct sky_sphere *c = sky_sphere_new();
	c->xf = s->xf;
	c->emission = s->emission;
	for (size_t i = 0; i < s->npigments; i++)
		sky_sphere_add(c, pigment_ref(s->pigments[i]));
	return c;
}

void sky_sphere_free(struct sky_sphere *s)
{
	if (!s)
		return;
	for (size_t i = 0; i < s->npigments; i++)
		pigment_unref(s->pigments[i]);
	free(s->pigments);
	free(s);
}

void rainbow_clear(struct rainbow *r)
{
	if (r->color_map)
		blend_map_unref(r->color_map);
	r->color_map = NULL;
}

void atmos_add_fog(struct atmosphere *a, const struct fog *f)
{
	struct fog *v = realloc(a->fogs, (a->nfogs + 1) * sizeof *v);
	if (!v) abort();
	a->fogs = v;
	a->fogs[a->nfogs++] = *f;
}

void atmos_add_rainbow(struct atmosphere *a, const struct rainbow *r)
{
	struct rainbow *v = realloc(a->rainbows, (a->nrainbows + 1) * sizeof *v);
	if (!v) abort();
	a->rainbows = v;
	a->rainbows[a->nrainbows++] = *r;
}

void atmos_set_sky(struct atmosphere *a, struct sky_sphere *s)
{
	sky_sphere_free(a->sky);
	a->sky = s;
}

void atmos_free(struct atmosphere *a)
{
	free(a->fogs);
	sky_sphere_free(a->sky);
	for (size_t i = 0; i < a->nrainbows; i++)
		rainbow_clear(&a->rainbows[i]);
	free(a->rainbows);
	a->fogs = NULL;
	a->sky = NULL;
	a->rainbows = NULL;
	a->nfogs = a->nrainbows = 0;
}

/* prepare.c: the prepare stage (see prepare.h). */
#include "render/prepare.h"

#include <stdlib.h>

const char *feature_name(enum feature f)
{
	switch (f) {
	case FEAT_SHADOWS: return "shadows";
	case FEAT_PHONG: return "phong highlights";
	case FEAT_SPECULAR: return "specular highlights";
	case FEAT_REFLECTION: return "reflection";
	default: return "?";
	}
}

unsigned prepare_features(const struct scene *s)
{
	unsigned f = 0;
	bool shadow_light = false, caster = false;
	for (size_t i = 0; i < s->nlights; i++)
		if (!s->lights[i].shadowless)
			shadow_light = true;
	for (size_t i = 0; i < s->nobjects; i++) {
		const struct object *o = s->objects[i];
		if (!(o->flags & OBJ_NO_SHADOW))
			caster = true;
		const struct finish *fin = o->tex ? &o->tex->finish : NULL;
		if (!fin)
			continue;
		if (fin->phong > 0)
			f |= FEAT_PHONG;
		if (fin->specular > 0)
			f |= FEAT_SPECULAR;
		if (rgb_max(fin->reflection) > 0)
			f |= FEAT_REFLECTION;
	}
	/* Without lights no highlight can appear either. */
	if (s->nlights == 0)
		f &= ~(unsigned)(FEAT_PHONG | FEAT_SPECULAR);
	if (shadow_light && caster)
		f |= FEAT_SHADOWS;
	return f;
}

struct prepared *prepare_scene(struct scene *s)
{
	struct prepared *p = calloc(1, sizeof *p);
	if (!p) abort();
	p->scene = s;
	struct object **bounded = malloc((s->nobjects ? s->nobjects : 1) * sizeof *bounded);
	p->unbounded = malloc((s->nobjects ? s->nobjects : 1) * sizeof *p->unbounded);
	if (!bounded || !p->unbounded) abort();
	size_t nb = 0;
	for (size_t i = 0; i < s->nobjects; i++) {
		struct object *o = s->objects[i];
		if (!o->tex)
			o->tex = texture_new();
		o->bounds = object_world_bounds(o);
		if (aabb_is_finite(o->bounds))
			bounded[nb++] = o;
		else
			p->unbounded[p->nunbounded++] = o;
	}
	p->bvh = bvh_build(bounded, nb);
	free(bounded);
	p->features = prepare_features(s);
	p->max_depth = s->gs.max_trace_level;
	return p;
}

void prepared_free(struct prepared *p)
{
	if (!p) return;
	bvh_free(p->bvh);
	free(p->unbounded);
	free(p);
}

/* prepare.c: the prepare stage (see prepare.h). */
#include "render/prepare.h"

#include "geom/csg.h"

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

/* The effects a texture's finish can produce. */
static unsigned finish_features(const struct texture *t)
{
	unsigned f = 0;
	if (!t)
		return f;
	const struct finish *fin = &t->finish;
	if (fin->phong > 0)
		f |= FEAT_PHONG;
	if (fin->specular > 0)
		f |= FEAT_SPECULAR;
	if (rgb_max(fin->reflection_max) > 0)
		f |= FEAT_REFLECTION;
	return f;
}

/* The effects the surfaces of o (every leaf of a CSG) can produce. */
static unsigned object_features(struct object *o, bool *caster)
{
	unsigned f = 0;
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			f |= object_features(kids[i], caster);
		return f;
	}
	if (!(o->flags & OBJ_NO_SHADOW))
		*caster = true;
	f |= finish_features(o->tex);
	if (o->ops->textures) {
		struct texture *const *own;
		size_t n = o->ops->textures(o, &own);
		for (size_t i = 0; i < n; i++)
			f |= finish_features(own[i]);
	}
	return f;
}

unsigned prepare_features(const struct scene *s)
{
	unsigned f = 0;
	bool shadow_light = false, caster = false;
	for (size_t i = 0; i < s->nlights; i++)
		if (!s->lights[i].shadowless)
			shadow_light = true;
	for (size_t i = 0; i < s->nobjects; i++)
		f |= object_features(s->objects[i], &caster);
	/* Without lights no highlight can appear either. */
	if (s->nlights == 0)
		f &= ~(unsigned)(FEAT_PHONG | FEAT_SPECULAR);
	if (shadow_light && caster)
		f |= FEAT_SHADOWS;
	return f;
}

struct objlist {
	struct object **v;
	size_t n, cap;
};

static void objlist_push(struct objlist *l, struct object *o)
{
	if (l->n == l->cap) {
		l->cap = l->cap ? 2 * l->cap : 64;
		l->v = realloc(l->v, l->cap * sizeof *l->v);
		if (!l->v) abort();
	}
	l->v[l->n++] = o;
}

/* Number the primitives of o (CSG leaves included) in scene order, for
 * --signature's colours. */
static void number_leaves(struct object *o, unsigned *next)
{
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			number_leaves(kids[i], next);
	} else {
		o->id = (*next)++;
	}
}

/* Put o into the scene's hierarchy, or its children if it is a union that
 * may be split (POV-Ray's split_union). */
static void add_top(struct objlist *bounded, struct objlist *unbounded, struct object *o)
{
	struct object **kids;
	if (csg_splittable(o)) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			add_top(bounded, unbounded, kids[i]);
		return;
	}
	object_prepare(o);
	objlist_push(aabb_is_finite(o->bounds) ? bounded : unbounded, o);
}

struct prepared *prepare_scene(struct scene *s)
{
	struct prepared *p = calloc(1, sizeof *p);
	if (!p) abort();
	p->scene = s;
	struct texture *plain = texture_new();
	struct objlist bounded = {0}, unbounded = {0};
	unsigned next_id = 0;
	for (size_t i = 0; i < s->nobjects; i++) {
		object_fill_texture(s->objects[i], plain);
		number_leaves(s->objects[i], &next_id);
		add_top(&bounded, &unbounded, s->objects[i]);
	}
	texture_unref(plain);
	p->bvh = bvh_build(bounded.v, bounded.n);
	free(bounded.v);
	p->unbounded = (const struct object **)unbounded.v;
	p->nunbounded = unbounded.n;
	p->features = prepare_features(s);
	p->max_depth = s->gs.max_trace_level;
	return p;
}

void prepared_free(struct prepared *p)
{
	if (!p) return;
	bvh_free(p->bvh);
	free((void *)p->unbounded);
	free(p);
}

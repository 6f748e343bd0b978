/* light.c: light sources as scene records (see light.h). */
#include "scene/light.h"

#include "scene/object.h"

#include <string.h>

struct light light_default(void)
{
	struct light l;
	memset(&l, 0, sizeof l);
	l.kind = LIGHT_POINT;
	l.color = rgb_make(1, 1, 1);
	l.radius = 30;
	l.falloff = 45;
	l.tightness = 0;
	l.adaptive = -1;
	l.media_interaction = true;
	return l;
}

void light_copy_parts(struct light *c)
{
	if (c->looks_like)
		c->looks_like = object_copy(c->looks_like);
	if (c->projected_through)
		c->projected_through = object_copy(c->projected_through);
}

void light_free_parts(struct light *l)
{
	object_free(l->looks_like);
	object_free(l->projected_through);
	l->looks_like = NULL;
	l->projected_through = NULL;
}

void light_transform(struct light *l, const struct xform *t)
{
	l->pos = mat_point(&t->fwd, l->pos);
	l->point_at = mat_point(&t->fwd, l->point_at);
	l->axis1 = mat_dir(&t->fwd, l->axis1);
	l->axis2 = mat_dir(&t->fwd, l->axis2);
	if (l->looks_like)
		object_transform(l->looks_like, t);
	if (l->projected_through)
		object_transform(l->projected_through, t);
}

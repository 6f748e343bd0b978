/* collect.h: collectors for the crossings that a shape's hit enumerator
 * reports one by one, in any order (prism, lathe, sor and text walk their
 * pieces this way): the closest crossing, for the ray's first hit, or the
 * nearest `max` crossings sorted by distance, for CSG's all_hits. Each
 * takes (ctx, t, part, u) and returns whether the enumeration should go
 * on. */
#ifndef LUCENT_GEOM_COLLECT_H
#define LUCENT_GEOM_COLLECT_H

#include <stdbool.h>

#include "scene/object.h"

struct hit_closest {
	double t, u;
	int part;
	bool found;
};

static inline bool hit_take_closest(void *ctx, double t, int part, double u)
{
	struct hit_closest *c = ctx;
	if (!c->found || t < c->t) {
		c->t = t;
		c->part = part;
		c->u = u;
		c->found = true;
	}
	return true;
}

struct hit_all {
	const struct object *o;
	struct hit *out;
	int n, max;
};

/* Keep the `max` nearest crossings, sorted. */
static inline bool hit_take_all(void *ctx, double t, int part, double u)
{
	struct hit_all *a = ctx;
	if (a->max <= 0)
		return false;
	if (a->n == a->max && t >= a->out[a->n - 1].t)
		return true;
	int i = a->n < a->max ? a->n++ : a->n - 1;
	while (i > 0 && a->out[i - 1].t > t) {
		a->out[i] = a->out[i - 1];
		i--;
	}
	a->out[i] = (struct hit){.t = t, .obj = a->o, .part = part, .u = u};
	return true;
}

#endif

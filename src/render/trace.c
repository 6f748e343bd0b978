/* trace.c: ray casting and shading (see trace.h). */
#include "render/trace.h"

#include <stdlib.h>
#include <string.h>

void tracer_init(struct tracer *tr, const struct prepared *p)
{
	tr->p = p;
	memset(&tr->stats, 0, sizeof tr->stats);
	size_t n = p->scene->nlights ? p->scene->nlights : 1;
	tr->last_blocker = calloc(n, sizeof *tr->last_blocker);
	if (!tr->last_blocker) abort();
}

void tracer_free(struct tracer *tr)
{
	free(tr->last_blocker);
	tr->last_blocker = NULL;
}

double trace_epsilon(vec3 p, vec3 from)
{
	/* Coordinates carry a relative error of a few ulps (about 1e-16) per
	 * operation; 1e-9 of their magnitude is far above that and far below
	 * any feature a scene at that scale can have. */
	double m = fmax(v3_maxabs(p), v3_maxabs(from));
	return 1e-9 * m + 1e-300;
}

bool trace_closest(const struct prepared *p, const struct ray *r, double tmin, double tmax, unsigned skip, struct hit *h)
{
	bool found = bvh_intersect(p->bvh, r, tmin, tmax, skip, h, NULL);
	if (found)
		tmax = h->t;
	for (size_t i = 0; i < p->nunbounded; i++) {
		const struct object *o = p->unbounded[i];
		if (o->flags & skip)
			continue;
		struct hit th;
		if (object_intersect(o, r, tmin, tmax, &th)) {
			*h = th;
			tmax = th.t;
			found = true;
		}
	}
	return found;
}

/* Is the segment from pt toward light li (unit direction ldir, length dist)
 * blocked? pt has already been lifted off the surface by eps along the
 * normal. Tries the last blocker of this light first. */
static bool shadowed(struct tracer *tr, size_t li, vec3 pt, vec3 ldir, double dist, double eps)
{
	const struct prepared *p = tr->p;
	struct ray sr = {pt, ldir};
	double tmax = dist - 2 * eps;
	tr->stats.rays[RAY_SHADOW]++;
	struct hit h;
	const struct object *last = tr->last_blocker[li];
	if (last && object_intersect(last, &sr, 0, tmax, &h)) {
		tr->stats.shadow_cache_hits++;
		return true;
	}
	const struct object *blk = NULL;
	if (bvh_occluded(p->bvh, &sr, 0, tmax, OBJ_NO_SHADOW, &blk)) {
		tr->last_blocker[li] = blk;
		return true;
	}
	for (size_t i = 0; i < p->nunbounded; i++) {
		const struct object *o = p->unbounded[i];
		if (o->flags & OBJ_NO_SHADOW)
			continue;
		if (object_intersect(o, &sr, 0, tmax, &h)) {
			tr->last_blocker[li] = o;
			return true;
		}
	}
	return false;
}

/* --signature: a flat colour for primitive number id, hues spread by the
 * golden ratio so that neighbours in scene order differ clearly. */
static rgb signature_color(unsigned id)
{
	double h = fmod((id + 1) * 0.6180339887498949, 1.0) * 6.0, s = 0.75, v = 0.95;
	int i = (int)h;
	double f = h - i, pp = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
	switch (i) {
	case 0: return rgb_make(v, t, pp);
	case 1: return rgb_make(q, v, pp);
	case 2: return rgb_make(pp, v, t);
	case 3: return rgb_make(pp, q, v);
	case 4: return rgb_make(t, pp, v);
	default: return rgb_make(v, pp, q);
	}
}

rgb trace_ray(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, bool *hit_anything)
{
	const struct prepared *p = tr->p;
	const struct scene *s = p->scene;
	tr->stats.rays[kind]++;
	struct hit h;
	unsigned skip = kind == RAY_CAMERA ? OBJ_NO_IMAGE : kind == RAY_REFLECTED ? OBJ_NO_REFLECTION : 0;
	if (!trace_closest(p, r, 0, INFINITY, skip, &h)) {
		*hit_anything = false;
		return rgb_of(s->background);
	}
	*hit_anything = true;
	if (p->signature)
		return signature_color(h.obj->id);
	vec3 dir = v3_norm(r->dir);
	vec3 pt = v3_madd(r->org, r->dir, h.t);
	vec3 n = object_normal(h.obj, pt, &h);
	/* Shade the side the ray sees. A ray tangent to the surface sees its
	 * outside: there n.dir is rounding noise of either sign, and flipping
	 * on noise would light the point from inside (speckles along the
	 * tangent). 1e-9 is far above that noise (~1e-16 for unit vectors)
	 * and far below any real incidence a pixel can show. */
	if (v3_dot(n, dir) > 1e-9)
		n = v3_neg(n);
	double eps = trace_epsilon(pt, r->org);

	const struct texture *tex = h.obj->ops->texture_at ? h.obj->ops->texture_at(h.obj, &h) : NULL;
	if (!tex)
		tex = h.obj->tex;
	const struct finish *fin = &tex->finish;
	struct pattern_ctx pctx = {.p = pt, .normal = n, .dir = dir, .noise_generator = 2};
	rgb pig = rgb_of(pigment_eval(tex->pigment, &pctx));
	rgb col = rgb_mul(rgb_mul(fin->ambient, s->gs.ambient_light), pig);
	col = rgb_add(col, rgb_mul(fin->emission, pig));

	vec3 refl = v3_reflect(dir, n);
	unsigned feat = p->features;
	for (size_t li = 0; li < s->nlights; li++) {
		const struct light *l = &s->lights[li];
		vec3 lv = v3_sub(l->pos, pt);
		double dist = v3_len(lv);
		if (dist == 0)
			continue;
		vec3 ldir = v3_scale(lv, 1.0 / dist);
		double cosi = v3_dot(n, ldir);
		/* The side of the surface the light is on: the one the ray sees,
		 * or with double_illuminate the other one too. */
		vec3 ln = n;
		bool back = false;
		if (cosi <= 0) {
			if (!(h.obj->flags & OBJ_DOUBLE_ILLUMINATE) || cosi == 0)
				continue;
			ln = v3_neg(n);
			cosi = -cosi;
			back = true;
		}
		if ((feat & FEAT_SHADOWS) && !l->shadowless && shadowed(tr, li, v3_madd(pt, ln, eps), ldir, dist, eps))
			continue;
		rgb lc = l->color;
		if (fin->diffuse > 0) {
			double k = fin->diffuse * (fin->brilliance == 1.0 ? cosi : pow(cosi, fin->brilliance));
			col = rgb_add(col, rgb_scale(rgb_mul(lc, pig), k));
		}
		if (back)
			continue; /* the lit back side shows no highlight toward the viewer */
		if ((feat & FEAT_PHONG) && fin->phong > 0) {
			double c = v3_dot(refl, ldir);
			if (c > 0) {
				double k = fin->phong * pow(c, fin->phong_size);
				rgb hc = fin->metallic ? rgb_mul(lc, pig) : lc;
				col = rgb_add(col, rgb_scale(hc, k));
			}
		}
		if ((feat & FEAT_SPECULAR) && fin->specular > 0) {
			vec3 hv = v3_norm(v3_sub(ldir, dir));
			double c = v3_dot(n, hv);
			if (c > 0) {
				double k = fin->specular * pow(c, 1.0 / fin->roughness);
				rgb hc = fin->metallic ? rgb_mul(lc, pig) : lc;
				col = rgb_add(col, rgb_scale(hc, k));
			}
		}
	}

	if ((feat & FEAT_REFLECTION) && rgb_max(fin->reflection_max) > 0 && depth < p->max_depth) {
		struct ray rr = {v3_madd(pt, n, eps), refl};
		bool any;
		rgb rc = trace_ray(tr, &rr, depth + 1, RAY_REFLECTED, &any);
		col = rgb_add(col, rgb_mul(rc, fin->reflection_max));
	}
	return col;
}

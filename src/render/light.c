/* light.c: sampling lights (see light.h). The formulas are POV-Ray 3.7's,
 * measured by rendering tiny scenes with it:
 * - spotlight: 1 inside `radius`, 0 outside `falloff`, between them the
 *   smoothstep t²(3 − 2t) of t = (cos a − cos falloff) / (cos radius −
 *   cos falloff), times cos(a)^tightness; a falloff below the radius is
 *   the radius (a hard edge);
 * - cylinder: the same in the distance r from the axis, t = (falloff − r)
 *   / (falloff − radius), times (1 − r / falloff)^tightness; the light runs
 *   along the axis (shading and shadows, like a parallel light), and points
 *   behind it get none;
 * - fading: 2 / (1 + (d / fade_distance)^fade_power), d the distance to
 *   the light's location; for parallel and cylinder lights the signed
 *   distance to the plane through the location across the axis;
 * - area lights: sample (i, j) of an n1 x n2 grid sits at
 *   pos + axis1 (i / (n1 − 1) − ½) + axis2 (j / (n2 − 1) − ½); the shading
 *   uses pos, only shadows use the grid. A parallel or cylinder light's
 *   sample is a parallel light of its own, running from the sample toward
 *   point_at, shadows stopping at the plane through the sample across
 *   that way (so the penumbra is the grid's size seen from point_at).
 *   The grid is sampled by blocks:
 *   a block is the mean of its four corners when its sides are at most one
 *   step, or when it is at level `adaptive` or deeper and its corners agree
 *   (no two differ by more than 0.1, summed over r, g, b); otherwise it is
 *   the mean of its halves in each direction that is longer than one step,
 *   [a, ⌊(a+b)/2⌋] and [⌈(a+b)/2⌉, b]. Without `adaptive` every block is
 *   split. So 5 samples weigh 1/8 2/8 2/8 2/8 1/8, and 4 samples 1/4 each;
 * - circular: the square's point (u, v) in [−1, 1]² moves along its
 *   radius to length max(|u|, |v|);
 * - orient: the grid is turned to face the point: axis1 along d × z (d ×
 *   y when d is nearly ±z), axis2 along d × axis1, with their lengths;
 * - area_illumination: the diffuse and highlights are the plain mean over
 *   all n1 × n2 samples (whatever `adaptive` says), each lighting from its
 *   own direction with its own fading; a spotlight's cone moves to each
 *   sample with its axis unchanged, a cylinder light keeps the cylinder
 *   of its location. The shadows stay those above, and multiply the mean.
 *   Samples behind the surface add nothing, and the light counts even
 *   where its location is behind the surface or outside its cone. */
#include "render/light.h"

#include "math/hash.h"
#include "scene/object.h"

#include <stdlib.h>
#include <string.h>

enum { PURPOSE_JITTER_U = 0x4c4a5501, PURPOSE_JITTER_V = 0x4c4a5602 };

/* Mark in live[] the carrier groups of the CSGs in o's tree. */
static void mark_carriers(struct object *o, bool *live, size_t n)
{
	if (o->carried_lights > 0 && (size_t)o->carried_lights < n)
		live[o->carried_lights] = true;
	struct object **kids;
	if (o->ops->children) {
		size_t k = o->ops->children(o, &kids);
		for (size_t i = 0; i < k; i++)
			mark_carriers(kids[i], live, n);
	}
}

struct light_set *light_set_new(const struct prepared *p)
{
	const struct scene *sc = p->scene;
	unsigned feat = p->features;
	struct light_set *s = calloc(1, sizeof *s);
	if (!s) abort();
	s->n = sc->nlights;
	s->v = calloc(s->n ? s->n : 1, sizeof *s->v);
	if (!s->v) abort();
	for (size_t i = 0; i < s->n; i++) {
		const struct light *l = &sc->lights[i];
		struct light_rt *L = &s->v[i];
		L->l = l;
		L->pos = l->pos;
		L->color = l->color;
		vec3 ax = v3_sub(l->point_at, l->pos);
		double al = v3_len(ax);
		L->axis = al > 0 ? v3_scale(ax, 1 / al) : v3(0, 0, 1);
		L->along_axis = l->parallel || l->kind == LIGHT_CYLINDER;
		if ((feat & FEAT_SPOTLIGHTS) && l->kind != LIGHT_POINT) {
			double r = l->radius, f = l->falloff < l->radius ? l->radius : l->falloff;
			L->spot = l->kind == LIGHT_SPOT;
			L->cylinder = l->kind == LIGHT_CYLINDER;
			L->cos_radius = cos(r * (M_PI / 180));
			L->cos_falloff = cos(f * (M_PI / 180));
			L->radius = r;
			L->falloff = f;
			L->tightness = l->tightness;
		}
		L->fade = (feat & FEAT_LIGHT_FADE) && l->fade_distance > 0 && l->fade_power > 0;
		L->fade_distance = l->fade_distance;
		L->fade_power = l->fade_power;
		L->shadows = (feat & FEAT_SHADOWS) && !l->shadowless;
		L->highlights = !l->shadowless;
		bool grid = (feat & FEAT_AREA_LIGHTS) && l->area && l->size1 * l->size2 > 1;
		L->area = L->shadows && grid;
		/* area_illumination holds for shadowless area lights too (measured). */
		L->illum = grid && l->area_illumination;
		L->n1 = grid ? l->size1 : 1;
		L->n2 = grid ? l->size2 : 1;
		L->adaptive = l->adaptive;
		L->jitter = l->jitter;
		L->circular = l->circular;
		L->orient = l->orient;
		L->axis1 = l->axis1;
		L->axis2 = l->axis2;
		L->len1 = v3_len(l->axis1);
		L->len2 = v3_len(l->axis2);
		L->projector = l->projected_through;
		if (L->illum) {
			L->illum_off = s->illum_points;
			s->illum_points += (size_t)L->n1 * (size_t)L->n2;
		}
		L->slot = s->slots;
		s->slots += (size_t)L->n1;
		if ((size_t)L->n1 * (size_t)L->n2 > s->max_samples)
			s->max_samples = (size_t)L->n1 * (size_t)L->n2;
	}
	/* Group 0 (objects outside groups) sees the global lights; group g
	 * sees its own lights, and the global ones if the outermost group
	 * around it says global_lights. POV-Ray 3.7 gives an object in nested
	 * groups the lights of its innermost group only (measured: the
	 * manual's "inherit" does not happen), and ignores global_lights on
	 * the inner ones. */
	s->ngroups = sc->ngroups ? sc->ngroups : 1;
	/* Lights carried by CSGs are global lights when their CSG is in the
	 * scene, and light nothing when it was only declared. */
	bool *live = calloc(s->ngroups, sizeof *live);
	if (!live) abort();
	for (size_t i = 0; i < sc->nobjects; i++)
		mark_carriers(sc->objects[i], live, s->ngroups);
	s->group = calloc(s->ngroups, sizeof *s->group);
	s->ngroup = calloc(s->ngroups, sizeof *s->ngroup);
	if (!s->group || !s->ngroup) abort();
	for (size_t g = 0; g < s->ngroups; g++) {
		s->group[g] = malloc((s->n ? s->n : 1) * sizeof **s->group);
		if (!s->group[g]) abort();
		bool global = g == 0;
		if (g > 0) {
			int k = (int)g;
			for (int guard = 0; sc->groups[k].parent != 0 && guard < 100000; guard++)
				k = sc->groups[k].parent;
			global = sc->groups[k].global_lights;
		}
		for (size_t i = 0; i < s->n; i++) {
			int lg = sc->lights[i].group;
			if (lg > 0 && sc->groups[lg].carrier) {
				if (!live[lg])
					continue;
				lg = 0;
			}
			if (lg == 0 ? global : (size_t)lg == g)
				s->group[g][s->ngroup[g]++] = i;
		}
	}
	free(live);
	return s;
}

void light_set_free(struct light_set *s)
{
	if (!s) return;
	for (size_t g = 0; g < s->ngroups; g++)
		free(s->group[g]);
	free(s->group);
	free(s->ngroup);
	free(s->v);
	free(s);
}

/* POV-Ray's smooth edge: 0 at t <= 0, 1 at t >= 1. */
static double smooth(double t)
{
	return t <= 0 ? 0 : t >= 1 ? 1 : t * t * (3 - 2 * t);
}

/* The way from pt to the light at lpos whose light runs along the unit
 * axis (for parallel and cylinder lights): out's direction and shadow
 * distance, atten 0. Returns the distance that fades the light: to lpos,
 * or for light along an axis the signed distance to the light's plane
 * (measured: constant over a plane across the axis; negative behind it). */
static double light_way(const struct light_rt *L, vec3 lpos, vec3 axis, vec3 pt, struct light_ray *out)
{
	vec3 lv = v3_sub(lpos, pt);
	out->atten = 0;
	if (L->along_axis) {
		out->dir = v3_neg(axis);
		/* Shadows are cast between the point and the light's plane. */
		double h = v3_dot(lv, out->dir);
		out->dist = h > 0 ? h : 0;
		return h;
	}
	double d = v3_len(lv);
	if (d == 0) {
		out->dir = v3(0, 0, 0);
		out->dist = 0;
	} else {
		out->dir = v3_scale(lv, 1 / d);
		out->dist = d;
	}
	return d;
}

/* The cone of a spotlight or cylinder light at lpos with the given axis,
 * at pt: 1 inside the radius, 0 outside the falloff; 1 for other lights. */
static double light_cone(const struct light_rt *L, vec3 lpos, vec3 axis, vec3 pt)
{
	vec3 lv = v3_sub(lpos, pt);
	double atten = 1;
	if (L->spot) {
		/* The angle between the axis and the way from the light to pt. */
		double d = v3_len(lv);
		if (d == 0)
			return 1;
		double c = -v3_dot(lv, axis) / d;
		if (c < L->cos_falloff)
			return 0;
		if (c < L->cos_radius)
			atten = smooth((c - L->cos_falloff) / (L->cos_radius - L->cos_falloff));
		if (L->tightness != 0)
			atten *= c > 0 ? pow(c, L->tightness) : 0;
	} else if (L->cylinder) {
		double along = -v3_dot(lv, axis);
		if (along < 0)
			return 0;
		double r = v3_len(v3_madd(lv, axis, along));
		if (r >= L->falloff)
			return 0;
		if (r > L->radius)
			atten = smooth((L->falloff - r) / (L->falloff - L->radius));
		if (L->tightness != 0)
			atten *= pow(1 - r / L->falloff, L->tightness);
	}
	return atten;
}

/* Fading at distance d (light_way's). POV-Ray raises a negative distance
 * to the power as it is (measured: 0 light at -3 with fade_distance 1,
 * power 1); where that has no real value, or the light would be negative
 * or infinite, none is counted. */
static double light_fade(const struct light_rt *L, double d)
{
	if (!L->fade)
		return 1;
	double f = 2 / (1 + pow(d / L->fade_distance, L->fade_power));
	return isfinite(f) && f > 0 ? f : 0;
}

/* light_at for the light moved to lpos, running along axis. */
static bool light_from(const struct light_rt *L, vec3 lpos, vec3 axis, vec3 pt, struct light_ray *out)
{
	double d = light_way(L, lpos, axis, pt, out);
	if (!L->along_axis && d == 0)
		return false;
	double atten = light_cone(L, lpos, axis, pt);
	if (atten <= 0)
		return false;
	out->atten = atten * light_fade(L, d);
	return out->atten > 0;
}

bool light_at(const struct light_rt *L, vec3 pt, struct light_ray *out)
{
	return light_from(L, L->pos, L->axis, pt, out);
}

void area_scratch_init(struct area_scratch *a, size_t max_samples)
{
	size_t n = max_samples ? max_samples : 1;
	a->val = malloc(n * sizeof *a->val);
	a->stamp = calloc(n, sizeof *a->stamp);
	if (!a->val || !a->stamp) abort();
	a->now = 0;
	a->n = n;
}

void area_scratch_free(struct area_scratch *a)
{
	free(a->val);
	free(a->stamp);
	a->val = NULL;
	a->stamp = NULL;
}

/* One area-light evaluation at a point. */
struct area_run {
	const struct light_rt *L;
	struct area_scratch *sc;
	area_test_fn test;
	void *ctx;
	vec3 base;        /* the grid's centre: the light's location */
	vec3 pt;          /* the point lit */
	vec3 a1, a2;      /* the (oriented) edge vectors */
	uint32_t hx, hy;  /* the point's hash, for jitter */
};

/* Where sample (i, j) of the grid lies for this point. */
static vec3 area_point(const struct area_run *r, int i, int j)
{
	const struct light_rt *L = r->L;
	uint32_t k = (uint32_t)j * (uint32_t)L->n1 + (uint32_t)i;
	double u = L->n1 > 1 ? 2.0 * i / (L->n1 - 1) - 1 : 0;
	double v = L->n2 > 1 ? 2.0 * j / (L->n2 - 1) - 1 : 0;
	if (L->jitter) {
		/* Anywhere in the sample's cell. */
		if (L->n1 > 1)
			u += (hash_uniform(r->hx, r->hy, k, PURPOSE_JITTER_U) - 0.5) * 2.0 / (L->n1 - 1);
		if (L->n2 > 1)
			v += (hash_uniform(r->hx, r->hy, k, PURPOSE_JITTER_V) - 0.5) * 2.0 / (L->n2 - 1);
	}
	if (L->circular && (u != 0 || v != 0)) {
		double m = fmax(fabs(u), fabs(v)) / sqrt(u * u + v * v);
		u *= m;
		v *= m;
	}
	return v3_madd(v3_madd(r->base, r->a1, u / 2), r->a2, v / 2);
}

/* A parallel or cylinder light's grid point q is a light of its own along
 * q -> point_at (POV-Ray 3.7, measured: the penumbra narrows as point_at
 * moves away, and each point's shadows stop at the plane through it across
 * its direction): its unit direction toward q. */
static vec3 axis_of(const struct light_rt *L, vec3 q)
{
	vec3 d = v3_sub(L->l->point_at, q);
	double n = v3_len(d);
	return n > 0 ? v3_scale(d, 1 / n) : L->axis;
}

/* The target of the shadow test of such a grid point q from pt: where the
 * way toward it leaves its plane; pt itself when pt is beyond the plane. */
static vec3 axis_target(const struct light_rt *L, vec3 q, vec3 pt)
{
	vec3 d = v3_neg(axis_of(L, q));
	double h = v3_dot(v3_sub(q, pt), d);
	return h > 0 ? v3_madd(pt, d, h) : pt;
}

/* The result of sample (i, j), tested once per point. */
static rgb area_sample(struct area_run *r, int i, int j)
{
	size_t k = (size_t)j * (size_t)r->L->n1 + (size_t)i;
	if (r->sc->stamp[k] == r->sc->now)
		return r->sc->val[k];
	vec3 q = area_point(r, i, j);
	rgb c = r->test(r->ctx, r->L->along_axis ? axis_target(r->L, q, r->pt) : q, i);
	r->sc->val[k] = c;
	r->sc->stamp[k] = r->sc->now;
	return c;
}

static bool differ(rgb a, rgb b)
{
	return fabs(a.r - b.r) + fabs(a.g - b.g) + fabs(a.b - b.b) > 0.1;
}

/* Block [u1, u2] x [v1, v2] of the grid at subdivision `level`. */
static rgb area_block(struct area_run *r, int u1, int v1, int u2, int v2, int level)
{
	rgb c00 = area_sample(r, u1, v1), c10 = area_sample(r, u2, v1);
	rgb c01 = area_sample(r, u1, v2), c11 = area_sample(r, u2, v2);
	bool leaf = u2 - u1 <= 1 && v2 - v1 <= 1;
	if (!leaf && r->L->adaptive >= 0 && level >= r->L->adaptive) {
		leaf = !(differ(c00, c10) || differ(c00, c01) || differ(c00, c11) || differ(c10, c01) ||
		         differ(c10, c11) || differ(c01, c11));
	}
	if (leaf)
		return rgb_scale(rgb_add(rgb_add(c00, c10), rgb_add(c01, c11)), 0.25);
	int ua[2] = {u1, u1}, ub[2] = {u2, u2}, va[2] = {v1, v1}, vb[2] = {v2, v2};
	int nu = 1, nv = 1;
	if (u2 - u1 > 1) {
		ub[0] = (u1 + u2) / 2;
		ua[1] = (u1 + u2 + 1) / 2;
		nu = 2;
	}
	if (v2 - v1 > 1) {
		vb[0] = (v1 + v2) / 2;
		va[1] = (v1 + v2 + 1) / 2;
		nv = 2;
	}
	rgb sum = rgb_make(0, 0, 0);
	for (int a = 0; a < nu; a++)
		for (int b = 0; b < nv; b++)
			sum = rgb_add(sum, area_block(r, ua[a], va[b], ub[a], vb[b], level + 1));
	return rgb_scale(sum, 1.0 / (nu * nv));
}

/* A 32-bit hash of a point, for jitter. */
static uint32_t point_hash(vec3 p, int which)
{
	uint64_t b[3];
	memcpy(&b[0], &p.x, 8);
	memcpy(&b[1], &p.y, 8);
	memcpy(&b[2], &p.z, 8);
	uint64_t h = hash_mix(b[0] ^ hash_mix(b[1] ^ hash_mix(b[2] + (uint64_t)which)));
	return (uint32_t)(h >> 32);
}

/* Set up r for area light L seen from pt: the grid's centre and axes
 * (turned to face pt with orient) and the point's hash for jitter. */
static void area_run_init(struct area_run *r, const struct light_rt *L, vec3 pt)
{
	r->L = L;
	r->a1 = L->axis1;
	r->a2 = L->axis2;
	r->base = L->pos;
	r->pt = pt;
	if (L->orient) {
		/* Face the point: the axes across the way from the light to it. */
		vec3 d = v3_norm(v3_sub(pt, L->pos));
		vec3 up = fabs(fabs(d.z) - 1) < 0.01 ? v3(0, 1, 0) : v3(0, 0, 1);
		vec3 a = v3_cross(d, up);
		double al = v3_len(a);
		if (al > 0) {
			a = v3_scale(a, 1 / al);
			vec3 b = v3_norm(v3_cross(d, a));
			r->a1 = v3_scale(a, L->len1);
			r->a2 = v3_scale(b, L->len2);
		}
	}
	if (L->jitter) {
		r->hx = point_hash(pt, 0);
		r->hy = point_hash(pt, 1);
	}
}

rgb light_area(const struct light_rt *L, vec3 pt, struct area_scratch *sc,
               area_test_fn test, void *ctx)
{
	struct area_run r = {.sc = sc, .test = test, .ctx = ctx};
	area_run_init(&r, L, pt);
	if (++sc->now == 0) {
		/* The stamps wrapped around: forget them all. */
		memset(sc->stamp, 0, sc->n * sizeof *sc->stamp);
		sc->now = 1;
	}
	return area_block(&r, 0, 0, L->n1 - 1, L->n2 - 1, 0);
}

bool light_area_points(const struct light_rt *L, vec3 pt, struct light_point *out)
{
	struct area_run r = {0};
	area_run_init(&r, L, pt);
	/* Each point is the light moved there, with its own fading; a
	 * spotlight's cone moves with it, its axis kept; a parallel or cylinder
	 * light's points run toward point_at, and a cylinder keeps the
	 * centre's cylinder (measured on POV-Ray 3.7). */
	double cyl = L->cylinder ? light_cone(L, L->pos, L->axis, pt) : 0;
	bool any = false;
	for (int j = 0; j < L->n2; j++)
		for (int i = 0; i < L->n1; i++) {
			struct light_ray q;
			struct light_point *o = &out[(size_t)j * (size_t)L->n1 + (size_t)i];
			vec3 at = area_point(&r, i, j);
			if (L->cylinder) {
				double d = light_way(L, at, axis_of(L, at), pt, &q);
				q.atten = cyl * light_fade(L, d);
			} else {
				light_from(L, at, L->along_axis ? axis_of(L, at) : L->axis, pt, &q);
			}
			o->dir = q.dir;
			o->atten = q.atten;
			any |= q.atten > 0;
		}
	return any;
}

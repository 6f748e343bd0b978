/* trace.c: ray casting and shading (see trace.h). The order of the terms
 * and how layers, reflection and transmission combine follow what POV-Ray
 * 3.7 renders (measured; see shade.c for the single formulas). */
#include "render/trace.h"

#include "image/image.h"
#include "math/hash.h"
#include "render/atmos.h"
#include "render/shade.h"

#include <stdlib.h>
#include <string.h>

/* One light as seen from the surface being shaded. */
struct lit {
	vec3 dir;    /* unit, toward the light */
	rgb color;   /* what arrives through transparent surfaces; black: in shadow */
	bool back;   /* the light is behind the face the ray sees */
	bool on;     /* lights the surface at all */
	bool highlights; /* makes highlights (shadowless lights make none) */
	const struct light_point *pts; /* area_illumination: the grid's points; NULL: dir alone */
	size_t npts;
};

void tracer_init(struct tracer *tr, const struct prepared *p)
{
	tr->p = p;
	memset(&tr->stats, 0, sizeof tr->stats);
	tr->lights = light_set_new(p);
	size_t n = p->scene->nlights ? p->scene->nlights : 1;
	tr->last_blocker = calloc(tr->lights->slots ? tr->lights->slots : 1, sizeof *tr->last_blocker);
	tr->lit = calloc(n, sizeof *tr->lit);
	tr->illum = malloc((tr->lights->illum_points ? tr->lights->illum_points : 1) * sizeof *tr->illum);
	if (!tr->last_blocker || !tr->lit || !tr->illum) abort();
	area_scratch_init(&tr->area, tr->lights->max_samples);
	tr->camera_limit = camera_ray_limit(&p->scene->camera);
	tr->stop = NULL;
}

void tracer_free(struct tracer *tr)
{
	free(tr->last_blocker);
	free(tr->lit);
	free(tr->illum);
	light_set_free(tr->lights);
	area_scratch_free(&tr->area);
	tr->last_blocker = NULL;
	tr->lit = NULL;
	tr->illum = NULL;
	tr->lights = NULL;
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
	/* Unbounded objects first, and a later hit must be strictly nearer:
	 * where a plane and a bounded object's face coincide (a glass box
	 * standing on a floor), the plane wins the tie, as in POV-Ray. */
	bool found = false;
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
	struct hit bh;
	if (bvh_intersect(p->bvh, r, tmin, tmax, skip, &bh, NULL)) {
		*h = bh;
		found = true;
	}
	return found;
}

/* Is the segment from pt along the unit direction ldir (length dist)
 * blocked? pt has already been lifted off the surface by eps along the
 * normal. Tries first the object that last blocked last-blocker slot
 * `slot` (a light, or a grid column of an area light). */
static bool shadowed(struct tracer *tr, size_t slot, vec3 pt, vec3 ldir, double dist, double eps)
{
	const struct prepared *p = tr->p;
	struct ray sr = {pt, ldir};
	double tmax = dist - 2 * eps;
	tr->stats.rays[RAY_SHADOW]++;
	struct hit h;
	const struct object *last = tr->last_blocker[slot];
	/* A loose object is skipped where the ray misses its box, as in the
	 * hierarchy (bvh.c). */
	if (last && (!last->loose || object_ray_meets_box(last->bounds, &sr, 0, tmax)) &&
	    object_intersect(last, &sr, 0, tmax, &h)) {
		tr->stats.shadow_cache_hits++;
		return true;
	}
	const struct object *blk = NULL;
	if (bvh_occluded(p->bvh, &sr, 0, tmax, OBJ_NO_SHADOW, &blk)) {
		tr->last_blocker[slot] = blk;
		return true;
	}
	for (size_t i = 0; i < p->nunbounded; i++) {
		const struct object *o = p->unbounded[i];
		if (o->flags & OBJ_NO_SHADOW)
			continue;
		if (object_intersect(o, &sr, 0, tmax, &h)) {
			tr->last_blocker[slot] = o;
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

enum { MAX_LAYERS = 32, SHADOW_CROSSINGS = 64 };

/* Everything the layers of one hit share. */
struct surface {
	vec3 pt;                     /* the hit point */
	vec3 dir;                    /* unit ray direction */
	vec3 n;                      /* unit geometric normal, facing the ray */
	double eps;                  /* offset for secondary rays */
	const struct object *obj;    /* the primitive hit */
	struct pattern_ctx ctx;      /* patterns at the world point */
	struct pattern_ctx uvctx;    /* patterns under uv_mapping: (u, v, 0) */
	const struct medium *med;    /* the interiors the ray travels in */
	const struct interior *in;   /* the object's interior (never NULL with FEAT_MEDIA) */
	bool leaving;                /* the ray leaves that interior here */
	double dist;                 /* the length of the ray that reached pt */
	int depth;
	unsigned skip;               /* the objects that ray could not see, which the
	                              * transmitted ray inherits */
};

/* The default interior of objects without one, when media are not tracked. */
static const struct interior default_interior = {.refs = 1, .ior = 1, .dispersion = 1, .dispersion_samples = 7};

static const struct pattern_ctx *ctx_for(const struct surface *s, const struct pattern *pt)
{
	return pt->uv_mapping ? &s->uvctx : &s->ctx;
}

/* The ior of interior `in` for light of the given hue (see
 * shade_dispersion_hue; 0 for light that is not dispersed). */
static double interior_ior(const struct interior *in, double hue)
{
	return hue != 0 && interior_dispersion(in) != 1 ? in->ior * pow(in->dispersion, hue) : in->ior;
}

/* The ior of the innermost interior of m (air: 1) for the ray that
 * travels in it, by the band of the spectrum it carries. */
static double medium_ior(const struct medium *m)
{
	return m && m->n ? interior_ior(m->in[m->n - 1], m->hue) : 1.0;
}

static bool medium_has(const struct medium *m, const struct interior *in)
{
	for (int i = 0; m && i < m->n; i++)
		if (m->in[i] == in)
			return true;
	return false;
}

/* The medium after crossing the surface of interior `in` of object o:
 * entered (pushed) or left (removed). Like POV-Ray, the ray only counts
 * crossings: an interior it meets again is left, whatever the geometry
 * (behind a clear disc the ray stays "inside" it; in the overlap of two
 * spheres of one union it is outside their shared interior). */
static void medium_cross(const struct medium *m, const struct interior *in, const struct object *o,
                         struct medium *out)
{
	out->n = 0;
	out->solid = 0;
	out->dispersed = m && m->dispersed;
	out->hue = m ? m->hue : 0;
	bool removed = false;
	for (int i = 0; m && i < m->n; i++) {
		if (m->in[i] == in) {
			removed = true;
			continue;
		}
		if (m->solid & (UINT32_C(1) << i))
			out->solid |= UINT32_C(1) << out->n;
		out->in[out->n++] = m->in[i];
	}
	if (!removed && out->n < MEDIUM_MAX) {
		if (!(o->flags & OBJ_HOLLOW))
			out->solid |= UINT32_C(1) << out->n;
		out->in[out->n++] = in;
	}
}

/* The colour of pigment pg at s. Below quality 6 a patterned pigment with
 * a quick_color shows that colour, as in POV-Ray. */
static struct rgbft pigment_at(const struct prepared *p, const struct pigment *pg, const struct surface *s)
{
	if (p->quality < 6 && pg && pg->kind != PIGMENT_SOLID && pg->quick)
		return pg->color;
	return pigment_eval(pg, ctx_for(s, &pg->pat));
}

/* A layer of a stack that is itself patterned (POV-Ray forbids this in the
 * language; a texture built otherwise gets the entry the pattern favours). */
static const struct texture *plain_of(const struct texture *t, const struct surface *s)
{
	for (int guard = 0; t && t->kind != TEX_PLAIN && guard < 64; guard++) {
		const struct blend_map *m = t->map;
		if (!m || m->n == 0)
			return NULL;
		int i;
		if (t->kind == TEX_MATERIAL) {
			struct rgbft c;
			image_map_eval(&t->pat.img, pattern_point(&t->pat, ctx_for(s, &t->pat)->p), &c, &i);
		} else if (pattern_is_block(t->pat.kind)) {
			i = (int)pattern_value(&t->pat, ctx_for(s, &t->pat));
		} else {
			int lo, hi;
			double w;
			blend_map_find(m, pattern_value(&t->pat, ctx_for(s, &t->pat)), &lo, &hi, &w);
			i = w < 0.5 ? lo : hi;
		}
		i = i < 0 ? 0 : i >= m->n ? m->n - 1 : i;
		t = m->e[i].item;
	}
	return t;
}

/* POV-Ray's grey of a colour (its weights for the transmit channel that
 * a filtering surface passes on, measured with +UA). */
static double gray_of(rgb c)
{
	return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

/* What a plain layer lets through: filter * colour + transmit. */
static rgb layer_filter(struct rgbft c)
{
	return rgb_make(c.f * c.r + c.t, c.f * c.g + c.t, c.f * c.b + c.t);
}

/* The share of light the texture stack t lets through at s (product of
 * its layers; patterned textures blend their entries'). */
static rgb surface_filter(const struct texture *t, const struct surface *s)
{
	rgb f = rgb_make(1, 1, 1);
	for (; t; t = t->next) {
		if (t->kind == TEX_PATTERNED && t->map && !pattern_is_block(t->pat.kind)) {
			int lo, hi;
			double w;
			blend_map_find(t->map, pattern_value(&t->pat, ctx_for(s, &t->pat)), &lo, &hi, &w);
			rgb a = t->map->e[lo].item ? surface_filter(t->map->e[lo].item, s) : rgb_make(1, 1, 1);
			rgb b = t->map->e[hi].item ? surface_filter(t->map->e[hi].item, s) : rgb_make(1, 1, 1);
			return rgb_mul(f, rgb_add(rgb_scale(a, 1 - w), rgb_scale(b, w)));
		}
		const struct texture *pl = plain_of(t, s);
		if (!pl)
			return f;
		if (pl != t)
			return rgb_mul(f, surface_filter(pl, s));
		f = rgb_mul(f, layer_filter(pigment_eval(pl->pigment, ctx_for(s, &pl->pigment->pat))));
		if (rgb_max(f) <= 0)
			break;
	}
	return f;
}

/* The textures an object blends at the world point pt (object.h's
 * texture_blend), with their weights; 0 if it has none there. */
enum { TEXTURE_BLEND_MAX = 32 };
static int texture_blend_at(const struct object *o, vec3 pt, const struct texture **tex, double *w)
{
	if (!o->ops->texture_blend)
		return 0;
	vec3 q = o->has_xf ? mat_point(&o->xf.inv, pt) : pt;
	return o->ops->texture_blend(o, q, tex, w, TEXTURE_BLEND_MAX);
}

/* Fill the pattern contexts of s for a hit h on s->obj; gs gives the
 * noise generator of patterns without their own and the number of waves. */
static void surface_contexts(struct surface *s, const struct hit *h, bool uv_wanted, const struct global_settings *gs)
{
	s->ctx = (struct pattern_ctx){.p = s->pt, .normal = s->n, .dir = s->dir,
	                              .noise_generator = gs->noise_generator, .number_of_waves = gs->number_of_waves};
	s->uvctx = s->ctx;
	double uv[2] = {0, 0};
	const struct object *o = s->obj;
	if (uv_wanted && o->ops->uv) {
		vec3 q = o->has_xf ? mat_point(&o->xf.inv, s->pt) : s->pt;
		o->ops->uv(o, q, h, uv);
	}
	s->uvctx.p = v3(uv[0], uv[1], 0);
}

/* The light lc arriving at pt along ldir (length dist) through the
 * surfaces in between, for a shadow ray starting in medium med: black
 * when an opaque surface blocks it. Transparent surfaces multiply it by
 * their filter (and their fake caustics), interiors by their fading.
 * `slot` is the last-blocker slot of the light (or grid column). */
static rgb light_through(struct tracer *tr, size_t slot, rgb lc, vec3 pt, vec3 ldir, double dist, double eps,
                         const struct medium *med)
{
	const struct prepared *p = tr->p;
	if (!(p->features & FEAT_TRANSPARENCY))
		return shadowed(tr, slot, pt, ldir, dist, eps) ? rgb_make(0, 0, 0) : lc;
	struct ray sr = {pt, ldir};
	double tmax = dist - 2 * eps, t0 = 0, last = 0;
	struct medium m = {0};
	if (med && (p->features & FEAT_MEDIA))
		m = *med;
	for (int k = 0; k < SHADOW_CROSSINGS; k++) {
		struct hit h;
		tr->stats.rays[RAY_SHADOW]++;
		if (!trace_closest(p, &sr, t0, tmax, OBJ_NO_SHADOW, &h))
			break;
		struct surface s = {.obj = h.obj};
		s.pt = v3_madd(sr.org, sr.dir, h.t);
		s.dir = ldir;
		s.n = object_normal(h.obj, s.pt, &h);
		surface_contexts(&s, &h, (p->features & FEAT_UV) != 0, &p->scene->gs);
		const struct texture *tex = h.obj->ops->texture_at ? h.obj->ops->texture_at(h.obj, &h) : NULL;
		const struct texture *bt[TEXTURE_BLEND_MAX];
		double bw[TEXTURE_BLEND_MAX];
		int nb = texture_blend_at(h.obj, s.pt, bt, bw);
		rgb f = rgb_make(0, 0, 0);
		for (int i = 0; i < nb; i++)
			f = rgb_add(f, rgb_scale(surface_filter(bt[i] ? bt[i] : h.obj->tex, &s), bw[i]));
		if (nb == 0)
			f = surface_filter(tex ? tex : h.obj->tex, &s);
		lc = rgb_mul(lc, f);
		if (rgb_max(lc) <= 0)
			return rgb_make(0, 0, 0);
		const struct interior *in = h.obj->interior;
		if (in) {
			if ((p->features & FEAT_CAUSTICS) && in->caustics > 0)
				lc = rgb_scale(lc, shade_caustics(v3_dot(s.n, ldir), in->caustics));
			if (p->features & FEAT_MEDIA) {
				if (medium_has(&m, in) && (p->features & FEAT_FADE) && in->fade_distance > 0 && in->fade_power > 0)
					lc = rgb_mul(lc, shade_fade(in, h.t - last));
				struct medium next;
				medium_cross(&m, in, h.obj, &next);
				m = next;
			}
		}
		last = h.t;
		t0 = h.t + trace_epsilon(s.pt, pt);
	}
	return lc;
}

/* How far along the unit direction dir from pt light L passes through its
 * projected_through object before reaching the light (at most dist; 0:
 * infinitely far): where its shadows stop. Negative when the way misses
 * the object, so that no light arrives. */
static double projected_dist(const struct light_rt *L, vec3 pt, vec3 dir, double dist)
{
	struct ray r = {pt, dir};
	struct hit h;
	if (!object_intersect(L->projector, &r, 0, dist > 0 ? dist : INFINITY, &h))
		return -1;
	return h.t;
}

/* One shadow test of an area light's sample, for light_area. */
struct shadow_ctx {
	struct tracer *tr;
	const struct light_rt *L;
	vec3 from;                  /* the lit point, lifted off its surface */
	double eps;
	const struct medium *med;
	rgb lc;                     /* the light's colour there, cone and fading applied */
};

static rgb area_test(void *vctx, vec3 target, int column)
{
	const struct shadow_ctx *c = vctx;
	vec3 v = v3_sub(target, c->from);
	double d = v3_len(v);
	if (d == 0)
		return c->lc;
	vec3 dir = v3_scale(v, 1 / d);
	if (c->L->projector && (d = projected_dist(c->L, c->from, dir, d)) < 0)
		return rgb_make(0, 0, 0);
	return light_through(c->tr, c->L->slot + (size_t)column, c->lc, c->from, dir, d, c->eps, c->med);
}

/* Whether one of the n perturbed normals faces dir. */
static bool faces_any(const vec3 *normals, int n, vec3 dir)
{
	for (int i = 0; i < n; i++)
		if (v3_dot(normals[i], dir) > 0)
			return true;
	return false;
}

/* Light every light of s's light group casts on s (into tr->lit); false
 * if none reaches. normals are the layers' perturbed normals: a light
 * behind the surface that one of them faces still lights it, as in
 * POV-Ray (measured: a bumpy plane lit from below its horizon shows the
 * bumps that face the light, and a shadowless light past a bumpy
 * sphere's terminator lights it); the shadow ray then leaves from the
 * light's side of the surface. */
static bool gather_lights(struct tracer *tr, const struct surface *s, bool back_wanted,
                          const vec3 *normals, int nnormals)
{
	const struct light_set *ls = tr->lights;
	size_t g = (size_t)s->obj->light_group < ls->ngroups ? (size_t)s->obj->light_group : 0;
	if (ls->ngroup[g] < ls->n)
		for (size_t li = 0; li < ls->n; li++)
			tr->lit[li].on = false;
	bool any = false;
	for (size_t k = 0; k < ls->ngroup[g]; k++) {
		size_t li = ls->group[g][k];
		const struct light_rt *L = &ls->v[li];
		struct lit *l = &tr->lit[li];
		l->on = false;
		struct light_ray lr;
		/* An area_illumination light lights from its grid's points, whose
		 * cones are their own: its centre may be outside its cone. */
		if (!light_at(L, s->pt, &lr) && !(L->illum && v3_dot(lr.dir, lr.dir) > 0))
			continue;
		l->dir = lr.dir;
		double c = v3_dot(s->n, l->dir);
		if (c == 0)
			continue;
		l->back = c < 0;
		bool lift_back = l->back;
		if (l->back && !back_wanted) {
			/* Part of an area_illumination grid may still be in front
			 * (POV-Ray lights from those points, measured). */
			if (L->illum)
				lift_back = false;
			else if (!faces_any(normals, nnormals, l->dir))
				continue;
			l->back = false;
		}
		l->highlights = L->highlights;
		l->pts = NULL;
		l->npts = 0;
		vec3 side = lift_back ? v3_neg(s->n) : s->n;
		vec3 from = v3_madd(s->pt, side, s->eps);
		if (L->illum) {
			/* The cones and fading are those of each grid point
			 * (applied in the shading); the shadows are the grid's. */
			struct light_point *pts = tr->illum + L->illum_off;
			if (!light_area_points(L, from, pts))
				continue;
			l->pts = pts;
			l->npts = (size_t)L->n1 * (size_t)L->n2;
			lr.atten = 1;
		}
		rgb lc = lr.atten == 1 ? L->color : rgb_scale(L->color, lr.atten);
		l->color = lc;
		if (L->shadows && lr.dist > 0) {
			if (L->area) {
				struct shadow_ctx ctx = {tr, L, from, s->eps, s->med, lc};
				l->color = light_area(L, from, &tr->area, area_test, &ctx);
			} else {
				double d = lr.dist;
				if (!L->projector || (d = projected_dist(L, from, lr.dir, d)) >= 0)
					l->color = light_through(tr, L->slot, lc, from, lr.dir, d, s->eps, s->med);
				else
					l->color = rgb_make(0, 0, 0);
			}
		} else if (L->projector && projected_dist(L, from, lr.dir, lr.dist) < 0) {
			l->color = rgb_make(0, 0, 0);
		}
		l->on = rgb_max(l->color) > 0;
		any |= l->on;
	}
	return any;
}

/* One plain layer of a stack, evaluated at the surface. */
struct layer {
	const struct texture *t;
	const struct finish *fin;
	rgb pig;        /* the pigment's colour */
	double opacity; /* 1 - filter - transmit: the share the surface terms get */
	vec3 n;         /* the (perturbed) normal, facing the ray */
	rgb above;      /* what the layers above let through */
	rgb refl;       /* the reflection colour at this angle (before exponent) */
	double refl_w;  /* the reflected ray's share for adc_bailout (reflection_color) */
};

/* The reflection colour of finish f at a view whose incidence cosine is
 * cv, for pigment pig; n_rel is the relative ior for fresnel. *w gets the
 * share of the reflected ray that POV-Ray 3.7 weighs against adc_bailout
 * (measured by bisecting adc_bailout on a mirror at normal incidence):
 * with fresnel, the largest channel of the reflection at this angle
 * before metallic; otherwise the largest channel of the minimum and the
 * maximum reflection, whatever the angle and metallic ({0.1, 0.6} weighs
 * 0.6 where it reflects 0.1). */
static rgb reflection_color(const struct finish *f, rgb pig, double cv, double n_rel, double *w)
{
	rgb lo = f->reflection_min, hi = f->reflection_max;
	double k;
	if (f->reflection_fresnel)
		k = shade_fresnel(cv, n_rel);
	else
		k = f->reflection_falloff == 1 ? 1 - cv : pow(1 - cv, f->reflection_falloff);
	rgb r = rgb_add(lo, rgb_scale(rgb_add(hi, rgb_scale(lo, -1)), k));
	*w = f->reflection_fresnel ? rgb_max(r) : fmax(rgb_max(lo), rgb_max(hi));
	if (f->reflection_metallic > 0)
		r = rgb_mul(r, shade_metallic(pig, f->reflection_metallic, cv));
	return r;
}

/* The relative ior (beyond / before) fresnel reflection uses at s. It is
 * not always the one refraction uses (n1 / n2 of transmit(): the
 * interiors on top of the medium before and after the crossing). As
 * measured in POV-Ray 3.7 at normal incidence on nested and overlapping
 * spheres: entering an interior, the ray comes from the top one of its
 * medium (or air); leaving one, it goes from that interior's ior into air
 * if it was the only one, else into the top one of the medium before the
 * crossing, which is the one left itself when the objects are nested: a
 * sphere inside another (or inside a plane around the camera) reflects
 * nothing by fresnel where the ray leaves it. Three spheres overlapping
 * in a row (ior 1.5, 2, 2.5), one reflecting at a time, give 0.1025,
 * 0.0327 and 0.196: the first leaves into the third, the second into the
 * third. */
static double fresnel_ior(const struct surface *s)
{
	const struct medium *m = s->med;
	if (!s->leaving)
		return s->in->ior / medium_ior(m);
	return (m->n == 1 ? 1.0 : m->in[m->n - 1]->ior) / s->in->ior;
}

/* What the fading of s's interior leaves of the light transmitted through
 * s: POV-Ray 3.7 fades only there, where a ray leaves a fading interior,
 * by the length of the ray that reached the surface (measured in glass
 * slabs seen head-on: a clear sphere inside the slab, or a mirror at its
 * back, leaves only the slab's last stretch faded; an opaque object inside
 * it, the reflections inside it, and a ray that escapes from it to the
 * background are not faded at all). */
static rgb exit_fade(const struct prepared *p, const struct surface *s)
{
	const struct interior *in = s->in;
	if (!(p->features & FEAT_FADE) || !s->leaving || in->fade_distance <= 0 || in->fade_power <= 0)
		return rgb_make(1, 1, 1);
	return shade_fade(in, s->dist);
}

/* Does the light transmitted through s split into bands of the spectrum?
 * Only where it crosses a dispersing interior and is not a band already:
 * as in POV-Ray 3.7 (measured through prisms), a band keeps its hue and
 * splits no more, also in other dispersing objects, which refract it with
 * their ior at its hue. So a ray splits once, not at every surface. */
static bool disperses(const struct prepared *p, const struct surface *s)
{
	return (p->features & FEAT_DISPERSION) && interior_dispersion(s->in) != 1 && !(s->med && s->med->dispersed);
}

/* Is the transmitted ray through s, across normal n into medium `after`,
 * totally reflected? Rays that split are not: each band decides for
 * itself in transmit(). */
static bool total_internal(const struct prepared *p, const struct surface *s, vec3 n, const struct medium *after)
{
	double n1 = medium_ior(s->med), n2 = medium_ior(after);
	if (n1 == n2 || disperses(p, s))
		return false;
	vec3 d;
	return !shade_refract(s->dir, n, n1 / n2, &d);
}

static rgb trace_see(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, unsigned skip,
                     double weight, const struct medium *med, bool *hit_anything);

/* A ray of the transmitted light through s: refracted by the relative ior
 * (eta = n1 / n2), or split into the bands of the spectrum (disperses());
 * a band under total internal reflection is mirrored. (The caller handles
 * total internal reflection of the whole ray, total_internal.) */
static rgb transmit(struct tracer *tr, const struct surface *s, vec3 n, double weight, const struct medium *after)
{
	const struct prepared *p = tr->p;
	bool any;
	double n1 = medium_ior(s->med), n2 = medium_ior(after);
	if (disperses(p, s)) {
		/* One ray per band, through the iors of its hue, weighted by its
		 * colour. Each carries the full weight for adc_bailout (measured:
		 * a mirror of reflection 0.3 behind a dispersing slab shows at
		 * adc_bailout 0.3, with 2 or 5 samples). */
		rgb sum = rgb_make(0, 0, 0);
		int ns = s->in->dispersion_samples;
		struct medium band = *after, back = {0};
		if (s->med)
			back = *s->med;
		band.dispersed = back.dispersed = true;
		for (int i = 0; i < ns; i++) {
			band.hue = back.hue = shade_dispersion_hue(i, ns);
			double eta = medium_ior(&back) / medium_ior(&band);
			vec3 d;
			struct ray r;
			rgb c;
			if (shade_refract(s->dir, n, eta, &d)) {
				r = (struct ray){v3_madd(s->pt, n, -s->eps), d};
				c = trace_see(tr, &r, s->depth + 1, RAY_REFRACTED, s->skip, weight, &band, &any);
			} else {
				r = (struct ray){v3_madd(s->pt, n, s->eps), v3_reflect(s->dir, n)};
				c = trace_ray_in(tr, &r, s->depth + 1, RAY_REFLECTED, weight, &back, &any);
			}
			sum = rgb_add(sum, rgb_mul(c, shade_dispersion_color(i, ns)));
		}
		return sum;
	}
	vec3 d = s->dir;
	if (n1 != n2)
		shade_refract(s->dir, n, n1 / n2, &d);
	struct ray r = {v3_madd(s->pt, s->n, -s->eps), d};
	/* A ray that passes straight through (no change of ior) stays on its
	 * trace level, as in POV-Ray 3.7 (measured: eight clear faces in a row
	 * all show at max_trace_level 2; with ior 1.5 each face takes one). */
	return trace_see(tr, &r, n1 == n2 ? s->depth : s->depth + 1, RAY_REFRACTED, s->skip, weight, after, &any);
}

/* The diffuse light and highlights of layer y at s from a light lt
 * arriving along the unit direction ldir, n being the layer's normal on
 * the side the light is (dbl: the object has double_illuminate), before
 * the light's colour: zero when ldir is behind n. */
static rgb light_terms(unsigned feat, const struct layer *y, const struct surface *s, vec3 n, vec3 ldir,
                       const struct lit *lt, bool dbl)
{
	const struct finish *f = y->fin;
	double cosl = v3_dot(n, ldir);
	rgb acc = rgb_make(0, 0, 0);
	if (cosl <= 0)
		return acc;
	double kd = lt->back && !dbl ? f->diffuse_back : f->diffuse;
	if (kd != 0) {
		double k = kd * (f->brilliance == 1.0 ? cosl : pow(cosl, f->brilliance));
		if (f->crand > 0)
			k -= f->crand * hash_uniform((uint32_t)(s->pt.x * 1e4), (uint32_t)(s->pt.y * 1e4),
			                             (uint32_t)(s->pt.z * 1e4), 7) * kd;
		rgb d = rgb_scale(y->pig, k * y->opacity);
		if ((feat & FEAT_IRID) && f->irid != 0) {
			double cv = fabs(v3_dot(s->dir, n));
			rgb ir = shade_irid(f->irid, f->irid_thickness, (cosl + cv) / 2, rgb_make(0.70, 0.52, 0.48));
			d = rgb_mul(d, rgb_make(1 + ir.r, 1 + ir.g, 1 + ir.b));
		}
		acc = rgb_add(acc, d);
	}
	if (!lt->back && lt->highlights) {
		if ((feat & FEAT_PHONG) && f->phong > 0) {
			double c = v3_dot(v3_reflect(s->dir, n), ldir);
			if (c > 0) {
				rgb hc = f->metallic > 0 ? shade_metallic(y->pig, f->metallic, cosl) : rgb_make(1, 1, 1);
				acc = rgb_add(acc, rgb_scale(hc, f->phong * pow(c, f->phong_size)));
			}
		}
		if ((feat & FEAT_SPECULAR) && f->specular > 0) {
			double c = v3_dot(n, v3_norm(v3_sub(ldir, s->dir)));
			if (c > 0) {
				rgb hc = f->metallic > 0 ? shade_metallic(y->pig, f->metallic, cosl) : rgb_make(1, 1, 1);
				acc = rgb_add(acc, rgb_scale(hc, f->specular * pow(c, 1.0 / f->roughness)));
			}
		}
	}
	return acc;
}

/* The colour of the plain-texture stack t (t, t->next, ...) at s: each
 * layer's ambient, emission and diffuse light scaled by its opacity, its
 * highlights whole, both filtered by the layers above; the reflections of
 * every layer under a see-through one; and what comes through them all. */
static rgb shade_layers(struct tracer *tr, const struct texture *t, const struct surface *s, double weight)
{
	const struct prepared *p = tr->p;
	const struct scene *sc = p->scene;
	unsigned feat = p->features;
	struct layer L[MAX_LAYERS];
	int nl = 0;
	rgb filt = rgb_make(1, 1, 1);
	/* The share of the background the layers let through: the product
	 * of the grey of each layer's filter (measured with +UA). */
	double tpass = 1;
	bool back_wanted = (s->obj->flags & OBJ_DOUBLE_ILLUMINATE) != 0;
	struct medium after = {0};
	double n_rel = 1;
	if (feat & FEAT_MEDIA) {
		medium_cross(s->med, s->in, s->obj, &after);
		n_rel = fresnel_ior(s);
	}
	for (const struct texture *l = t; l && nl < MAX_LAYERS; l = l->next) {
		const struct texture *pl = plain_of(l, s);
		if (!pl)
			break;
		struct layer *y = &L[nl++];
		y->t = pl;
		y->fin = &pl->finish;
		struct rgbft c = pigment_at(p, pl->pigment, s);
		y->pig = rgb_of(c);
		y->opacity = 1 - c.f - c.t;
		y->n = s->n;
		if ((feat & FEAT_NORMALS) && pl->normal)
			y->n = normal_eval(pl->normal, s->n, ctx_for(s, &pl->normal->pat));
		y->above = filt;
		y->refl = rgb_make(0, 0, 0);
		y->refl_w = 0;
		if ((feat & FEAT_REFLECTION) && (rgb_max(y->fin->reflection_max) > 0 || rgb_max(y->fin->reflection_min) > 0))
			y->refl = reflection_color(y->fin, y->pig, fabs(v3_dot(s->dir, y->n)), n_rel, &y->refl_w);
		back_wanted |= y->fin->diffuse_back != 0;
		rgb lf = layer_filter(c);
		if (y->fin->conserve_energy)
			lf = rgb_mul(lf, rgb_make(1 - y->refl.r, 1 - y->refl.g, 1 - y->refl.b));
		filt = rgb_mul(filt, lf);
		tpass *= gray_of(lf);
		if (rgb_max(filt) <= 0 || pl != l)
			break;
	}
	/* Quality 0 and 1: full ambient light only. POV-Ray shows the
	 * pigments' colours as they are: each layer through the transparency
	 * of those above it, the last one whole (measured: a clear glass
	 * shows its colour, a clear top layer the one below). */
	tr->transmit = 0; /* until a transmitted ray says otherwise */
	if (p->quality < 2) {
		rgb c = rgb_make(0, 0, 0);
		for (int i = 0; i < nl; i++)
			c = rgb_add(c, rgb_mul(L[i].above, rgb_scale(L[i].pig, i == nl - 1 ? 1 : L[i].opacity)));
		return c;
	}

	rgb col = rgb_make(0, 0, 0);
	for (int i = 0; i < nl; i++) {
		const struct layer *y = &L[i];
		rgb a = rgb_add(rgb_mul(y->fin->ambient, sc->gs.ambient_light), y->fin->emission);
		col = rgb_add(col, rgb_mul(y->above, rgb_scale(rgb_mul(a, y->pig), y->opacity)));
	}

	vec3 normals[MAX_LAYERS];
	int nnormals = 0;
	if (feat & FEAT_NORMALS)
		for (int i = 0; i < nl; i++)
			normals[nnormals++] = L[i].n;
	if (sc->nlights && gather_lights(tr, s, back_wanted, normals, nnormals)) {
		bool dbl = (s->obj->flags & OBJ_DOUBLE_ILLUMINATE) != 0;
		for (size_t li = 0; li < sc->nlights; li++) {
			const struct lit *lt = &tr->lit[li];
			if (!lt->on)
				continue;
			for (int i = 0; i < nl; i++) {
				const struct layer *y = &L[i];
				vec3 n = lt->back ? v3_neg(y->n) : y->n;
				rgb acc;
				if (!lt->pts) {
					acc = light_terms(feat, y, s, n, lt->dir, lt, dbl);
				} else {
					/* area_illumination: the mean over the grid's points. */
					acc = rgb_make(0, 0, 0);
					for (size_t k = 0; k < lt->npts; k++)
						if (lt->pts[k].atten > 0)
							acc = rgb_add(acc, rgb_scale(light_terms(feat, y, s, n, lt->pts[k].dir, lt, dbl),
							                             lt->pts[k].atten));
					acc = rgb_scale(acc, 1.0 / (double)lt->npts);
				}
				col = rgb_add(col, rgb_mul(y->above, rgb_mul(acc, lt->color)));
			}
		}
	}

	if (s->depth < p->max_depth) {
		double bail = sc->gs.adc_bailout;
		/* POV-Ray 3.7 transmits a ray where both the grey of what the
		 * layers let through (filt, with conserve_energy's share) and the
		 * ray's weight times filt's largest channel reach adc_bailout; the
		 * latter is the transmitted ray's weight. Measured by bisecting
		 * adc_bailout behind one and two nested filtering boxes: rgbf
		 * <0.5, 1, 0.2, 0.6> alone weighs 0.456 (its grey), twice 0.36;
		 * white filter 0.9 then <0.5, 1, 0.2, 0.9> weighs 0.684, the
		 * second's grey not scaled by the first. */
		double tw = weight * rgb_max(filt);
		/* Quality below 6 transmits no ray (prepare_quality). */
		bool passes = (feat & FEAT_TRANSPARENCY) && p->quality >= 6 && rgb_max(filt) > 0 && gray_of(filt) >= bail;
		bool transmits = passes && tw >= bail;
		bool tir = passes && total_internal(p, s, L[0].n, &after);
		if (tir && !transmits) {
			/* Totally reflected light too weak to follow: where the grey
			 * passes, POV-Ray traces no reflection either (measured in a
			 * prism of filter 0.5 and reflection 0.9: at adc_bailout 0.3
			 * the object the mirrored ray would reach is not seen). Where
			 * the grey fails, the finish's reflection is traced as on an
			 * opaque surface (measured: with conserve_energy and fresnel
			 * reflection, whole under total reflection, the object comes
			 * back at higher adc_bailout, by the reflection). */
			tr->transmit = 0;
			return col;
		}
		if (transmits && tir) {
			/* Total internal reflection: POV-Ray then traces the mirrored
			 * ray alone and adds it whole, neither filtered by the pigment
			 * nor joined by the finish's reflection (measured from inside
			 * a glass half-space: the mirrored background comes back at
			 * full strength for filter 0.005 to 1, transmit 0.5, any
			 * pigment colour, reflection 0.3 with exponent 0.5, fresnel
			 * reflection, with or without conserve_energy). Its weight
			 * for adc_bailout is the transmitted ray's (measured with a
			 * mirror behind the reflection and adc_bailout 0.1 to 0.3). */
			struct ray r = {v3_madd(s->pt, L[0].n, s->eps), v3_reflect(s->dir, L[0].n)};
			bool any;
			rgb c = trace_ray_in(tr, &r, s->depth + 1, RAY_REFLECTED, tw, s->med, &any);
			tr->transmit = 0; /* a reflected ray passes nothing on */
			return rgb_add(col, rgb_mul(c, exit_fade(p, s)));
		}
		for (int i = 0; i < nl; i++) {
			const struct layer *y = &L[i];
			double w = weight * y->refl_w;
			/* POV-Ray traces a ray whose weight equals adc_bailout
			 * (measured: reflection 0.2 shows at adc_bailout 0.2). */
			if (w < bail || w <= 0 || rgb_max(y->refl) <= 0)
				continue;
			struct ray rr = {v3_madd(s->pt, s->n, s->eps), v3_reflect(s->dir, y->n)};
			bool any;
			rgb rc = trace_ray_in(tr, &rr, s->depth + 1, RAY_REFLECTED, w, s->med, &any);
			double e = y->fin->reflection_exponent;
			if (e != 1)
				rc = rgb_make(pow(fmax(rc.r, 0), 1 / e), pow(fmax(rc.g, 0), 1 / e), pow(fmax(rc.b, 0), 1 / e));
			col = rgb_add(col, rgb_mul(rc, y->refl));
		}
		double through = 0;
		if (transmits) {
			rgb c = transmit(tr, s, L[0].n, tw, &after);
			col = rgb_add(col, rgb_mul(rgb_mul(filt, c), exit_fade(p, s)));
			through = tpass * tr->transmit;
		}
		/* What no transmitted ray reaches is opaque (measured: below
		 * adc_bailout or at max_trace_level the alpha is 1). */
		tr->transmit = through;
	}
	return col;
}

/* The colour of texture t at s: patterned textures shade their entries in
 * full and blend the results by the pattern (as POV-Ray documents and
 * does); material maps take the entry the image's palette index names. */
static rgb shade_texture(struct tracer *tr, const struct texture *t, const struct surface *s, double weight)
{
	if (!t) {
		tr->transmit = 0;
		return rgb_make(0, 0, 0);
	}
	if (t->kind == TEX_PLAIN || !t->map || t->map->n == 0)
		return shade_layers(tr, t, s, weight);
	const struct blend_map *m = t->map;
	const struct pattern_ctx *ctx = ctx_for(s, &t->pat);
	int lo, hi;
	double w = 0;
	if (t->kind == TEX_MATERIAL) {
		struct rgbft c;
		image_map_eval(&t->pat.img, pattern_point(&t->pat, ctx->p), &c, &lo);
		hi = lo;
	} else if (pattern_is_block(t->pat.kind)) {
		lo = hi = (int)pattern_value(&t->pat, ctx);
	} else {
		blend_map_find(m, pattern_value(&t->pat, ctx), &lo, &hi, &w);
	}
	lo = lo < 0 ? 0 : lo >= m->n ? m->n - 1 : lo;
	hi = hi < 0 ? 0 : hi >= m->n ? m->n - 1 : hi;
	if (hi == lo || w <= 0)
		return shade_texture(tr, m->e[lo].item, s, weight);
	if (w >= 1)
		return shade_texture(tr, m->e[hi].item, s, weight);
	rgb a = shade_texture(tr, m->e[lo].item, s, weight * (1 - w));
	double ta = tr->transmit;
	rgb b = shade_texture(tr, m->e[hi].item, s, weight * w);
	tr->transmit = ta * (1 - w) + tr->transmit * w;
	return rgb_add(rgb_scale(a, 1 - w), rgb_scale(b, w));
}

/* trace_ray_in for a ray that cannot see the objects with a `skip` flag.
 * Camera rays skip no_image objects and reflected rays no_reflection ones;
 * a ray transmitted through a surface, refracted or not, skips what the ray
 * that reached the surface skipped (measured in POV-Ray: a no_image object
 * stays hidden behind a clear pane and behind glass of ior 1.5, and shows
 * through them in a mirror, where a no_reflection object is hidden). */
static rgb trace_see(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, unsigned skip,
                     double weight, const struct medium *med, bool *hit_anything)
{
	const struct prepared *p = tr->p;
	tr->stats.rays[kind]++;
	struct hit h;
	if (!trace_closest(p, r, 0, kind == RAY_CAMERA ? tr->camera_limit : INFINITY, skip, &h)) {
		vec3 dir = v3_norm(r->dir);
		struct rgbft bg = atmos_escape(p, dir);
		if (p->features & (FEAT_FOG | FEAT_RAINBOW))
			bg = atmos_apply(p, med, r->org, dir, ATMOS_MISS_DEPTH, bg);
		*hit_anything = false;
		tr->transmit = bg.t;
		return rgb_of(bg);
	}
	*hit_anything = true;
	if (p->signature) {
		tr->transmit = 0;
		return signature_color(h.obj->id);
	}
	/* Field by field: zeroing the whole struct first cost more than the
	 * rest of this setup (its two pattern contexts are surface_contexts'). */
	struct surface s;
	s.obj = h.obj;
	s.med = med;
	s.depth = depth;
	s.dist = h.t * v3_len(r->dir);
	s.skip = skip;
	s.leaving = false;
	s.dir = v3_norm(r->dir);
	s.pt = v3_madd(r->org, r->dir, h.t);
	s.n = object_normal(h.obj, s.pt, &h);
	/* Shade the side the ray sees. A ray tangent to the surface sees its
	 * outside: there n.dir is rounding noise of either sign, and flipping
	 * on noise would light the point from inside (speckles along the
	 * tangent). 1e-9 is far above that noise (~1e-16 for unit vectors)
	 * and far below any real incidence a pixel can show. */
	if (v3_dot(s.n, s.dir) > 1e-9)
		s.n = v3_neg(s.n);
	s.eps = trace_epsilon(s.pt, r->org);
	s.in = h.obj->interior ? h.obj->interior : &default_interior;
	if (p->features & FEAT_MEDIA)
		s.leaving = medium_has(med, s.in);
	surface_contexts(&s, &h, (p->features & FEAT_UV) != 0, &p->scene->gs);
	const struct texture *tex = h.obj->ops->texture_at ? h.obj->ops->texture_at(h.obj, &h) : NULL;
	const struct texture *bt[TEXTURE_BLEND_MAX];
	double bw[TEXTURE_BLEND_MAX];
	int nb = texture_blend_at(h.obj, s.pt, bt, bw);
	rgb col = rgb_make(0, 0, 0);
	double transmit = 0;
	for (int i = 0; i < nb; i++) {
		col = rgb_add(col, rgb_scale(shade_texture(tr, bt[i] ? bt[i] : h.obj->tex, &s, weight * bw[i]), bw[i]));
		transmit += tr->transmit * bw[i];
	}
	if (nb > 0)
		tr->transmit = transmit;
	else
		col = shade_texture(tr, tex ? tex : h.obj->tex, &s, weight);
	if (p->features & (FEAT_FOG | FEAT_RAINBOW)) {
		double len = v3_len(r->dir);
		struct rgbft c = {col.r, col.g, col.b, 0, tr->transmit};
		c = atmos_apply(p, med, r->org, v3_scale(r->dir, 1 / len), h.t * len, c);
		col = rgb_of(c);
		tr->transmit = c.t;
	}
	return col;
}

rgb trace_ray_in(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, double weight,
                 const struct medium *med, bool *hit_anything)
{
	unsigned skip = kind == RAY_CAMERA ? OBJ_NO_IMAGE : kind == RAY_REFLECTED ? OBJ_NO_REFLECTION : 0;
	return trace_see(tr, r, depth, kind, skip, weight, med, hit_anything);
}

rgb trace_ray(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, bool *hit_anything)
{
	const struct medium *m = tr->p->camera_medium.n ? &tr->p->camera_medium : NULL;
	rgb c = trace_ray_in(tr, r, depth, kind, 1.0, m, hit_anything);
	tr->camera_transmit += tr->transmit;
	tr->camera_rays++;
	return c;
}

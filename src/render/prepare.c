/* prepare.c: the prepare stage (see prepare.h). */
#include "render/prepare.h"

#include "geom/csg.h"
#include "image/image.h"
#include "render/camsample.h"

#include <stdlib.h>

const char *feature_name(enum feature f)
{
	switch (f) {
	case FEAT_SHADOWS: return "shadows";
	case FEAT_PHONG: return "phong highlights";
	case FEAT_SPECULAR: return "specular highlights";
	case FEAT_REFLECTION: return "reflection";
	case FEAT_TRANSPARENCY: return "transparency";
	case FEAT_REFRACTION: return "refraction";
	case FEAT_NORMALS: return "normals";
	case FEAT_IRID: return "iridescence";
	case FEAT_FADE: return "fading";
	case FEAT_DISPERSION: return "dispersion";
	case FEAT_CAUSTICS: return "caustics";
	case FEAT_FRESNEL: return "fresnel reflection";
	case FEAT_LAYERS: return "layered textures";
	case FEAT_UV: return "uv mapping";
	case FEAT_AREA_LIGHTS: return "area lights";
	case FEAT_SPOTLIGHTS: return "spotlight cones";
	case FEAT_LIGHT_FADE: return "light fading";
	case FEAT_FOCAL_BLUR: return "focal blur";
	case FEAT_FOG: return "fog";
	case FEAT_SKY: return "sky";
	case FEAT_RAINBOW: return "rainbow";
	case FEAT_ANTIALIAS: return "antialiasing";
	case FEAT_INTERIORS: return "fog inside objects";
	default: return "?";
	}
}

/* Can pigment pg let light through anywhere (a filter or transmit above
 * 0 in any colour it can give, a hole in a map, an image's alpha)? */
static bool pigment_transmits(const struct pigment *pg)
{
	if (!pg)
		return true;
	switch (pg->kind) {
	case PIGMENT_SOLID:
		return pg->color.f > 0 || pg->color.t > 0;
	case PIGMENT_IMAGE: {
		const struct image_mapping *m = &pg->pat.img;
		return m->once || m->has_filter_all || m->has_transmit_all || m->nentry > 0 || m->use_alpha ||
		       (m->img && m->img->has_alpha);
	}
	case PIGMENT_PATTERN:
		break;
	}
	if (pg->pat.kind == PAT_PIGMENT && pigment_transmits(pg->pat.pig))
		return true;
	const struct blend_map *m = pg->map;
	if (!m)
		return false;
	for (int i = 0; i < m->n; i++) {
		if (m->kind == MAP_COLOR && (m->e[i].color.f > 0 || m->e[i].color.t > 0))
			return true;
		if (m->kind == MAP_PIGMENT && pigment_transmits(m->e[i].item))
			return true;
	}
	return false;
}

static bool pattern_uv(const struct pattern *pt)
{
	return pt->uv_mapping;
}

/* The effects texture t (every layer and map entry) can produce. */
static unsigned texture_features(const struct texture *t, int depth)
{
	unsigned f = 0;
	for (; t && depth < 64; t = t->next, depth++) {
		if (t->kind != TEX_PLAIN) {
			f |= FEAT_LAYERS;
			if (pattern_uv(&t->pat))
				f |= FEAT_UV;
			for (int i = 0; t->map && i < t->map->n; i++)
				f |= texture_features(t->map->e[i].item, depth + 1);
			continue;
		}
		if (t->next)
			f |= FEAT_LAYERS;
		const struct finish *fin = &t->finish;
		if (fin->phong > 0)
			f |= FEAT_PHONG;
		if (fin->specular > 0)
			f |= FEAT_SPECULAR;
		if (rgb_max(fin->reflection_max) > 0 || rgb_max(fin->reflection_min) > 0) {
			f |= FEAT_REFLECTION;
			if (fin->reflection_fresnel)
				f |= FEAT_FRESNEL;
		}
		if (fin->irid != 0)
			f |= FEAT_IRID;
		if (pigment_transmits(t->pigment))
			f |= FEAT_TRANSPARENCY;
		if (t->pigment && pattern_uv(&t->pigment->pat))
			f |= FEAT_UV;
		if (t->normal) {
			f |= FEAT_NORMALS;
			if (pattern_uv(&t->normal->pat))
				f |= FEAT_UV;
		}
	}
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
	f |= texture_features(o->tex, 0);
	if (o->ops->textures) {
		struct texture *const *own;
		size_t n = o->ops->textures(o, &own);
		for (size_t i = 0; i < n; i++)
			f |= texture_features(own[i], 0);
	}
	const struct interior *in = o->interior;
	/* An interior matters where light can pass into it, and for fresnel
	 * reflection, which reads its ior. */
	if (in && (f & FEAT_TRANSPARENCY)) {
		if (in->ior != 1)
			f |= FEAT_REFRACTION;
		if (in->fade_distance > 0 && in->fade_power > 0)
			f |= FEAT_FADE;
		if (interior_dispersion(in) != 1)
			f |= FEAT_DISPERSION;
		if (in->caustics > 0)
			f |= FEAT_CAUSTICS;
	}
	return f;
}

unsigned prepare_features(const struct scene *s)
{
	unsigned f = 0;
	bool shadow_light = false, caster = false, area_light = false, illum_light = false;
	for (size_t i = 0; i < s->nlights; i++) {
		const struct light *l = &s->lights[i];
		if (!l->shadowless)
			shadow_light = true;
		/* Only the shadows of an area light differ from a point light's. */
		if (!l->shadowless && l->area && l->size1 * l->size2 > 1)
			area_light = true;
		/* area_illumination shades from the grid, shadows or not. */
		if (l->area && l->size1 * l->size2 > 1 && l->area_illumination)
			illum_light = true;
		if (l->kind != LIGHT_POINT)
			f |= FEAT_SPOTLIGHTS;
		if (l->fade_distance > 0 && l->fade_power > 0)
			f |= FEAT_LIGHT_FADE;
	}
	for (size_t i = 0; i < s->nobjects; i++)
		f |= object_features(s->objects[i], &caster);
	/* Without lights no highlight can appear either; shadowless lights
	 * make none (as in POV-Ray). */
	if (s->nlights == 0)
		f &= ~(unsigned)(FEAT_PHONG | FEAT_SPECULAR | FEAT_IRID | FEAT_CAUSTICS);
	if (!shadow_light)
		f &= ~(unsigned)(FEAT_PHONG | FEAT_SPECULAR);
	if (shadow_light && caster) {
		f |= FEAT_SHADOWS;
		if (area_light)
			f |= FEAT_AREA_LIGHTS;
	}
	if (illum_light)
		f |= FEAT_AREA_LIGHTS;
	for (size_t i = 0; i < s->atmos.nfogs; i++)
		if (s->atmos.fogs[i].distance > 0)
			f |= FEAT_FOG;
	for (size_t i = 0; i < s->atmos.nrainbows; i++)
		if (s->atmos.rainbows[i].color_map && s->atmos.rainbows[i].width > 0 && s->atmos.rainbows[i].distance > 0)
			f |= FEAT_RAINBOW;
	if (s->atmos.sky)
		f |= FEAT_SKY;
	/* Fog stops inside objects that are not hollow; a ray can only get
	 * into one through a see-through surface (or start there: the camera,
	 * see prepare_scene). */
	if ((f & (FEAT_FOG | FEAT_RAINBOW)) && (f & FEAT_TRANSPARENCY))
		f |= FEAT_INTERIORS;
	/* cameras: focal blur needs an aperture and blur_samples. */
	if (s->camera.aperture > 0 && s->camera.blur_samples_max > 0)
		f |= FEAT_FOCAL_BLUR;
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

/* Give every leaf of o without an interior a reference to in, so that the
 * leaves of one object share one (as POV-Ray's objects do) and a ray can
 * tell which one it is inside by pointer. */
static void fill_interior(struct object *o, struct interior *in)
{
	struct object **kids;
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			fill_interior(kids[i], in);
	} else if (!o->interior) {
		const struct finish *f = o->tex && o->tex->kind == TEX_PLAIN ? &o->tex->finish : NULL;
		if (f && (f->legacy_ior > 0 || f->legacy_caustics != 0)) {
			/* finish { ior caustics }: POV-Ray's pre-3.1 places */
			struct interior *own = interior_copy(in);
			if (f->legacy_ior > 0)
				own->ior = f->legacy_ior;
			own->caustics = f->legacy_caustics;
			o->interior = own;
		} else {
			o->interior = interior_ref(in);
		}
	}
}

/* The leaves of o in scene order, for same_hollow. */
static void collect_leaves(struct object *o, struct objlist *l)
{
	struct object **kids;
	if (!o->ops->children) {
		objlist_push(l, o);
		return;
	}
	size_t n = o->ops->children(o, &kids);
	for (size_t i = 0; i < n; i++)
		collect_leaves(kids[i], l);
}

/* Leaves ordered by interior, then by their place in the object. */
static int by_interior(const void *a, const void *b)
{
	const struct object *const *x = a, *const *y = b;
	uintptr_t ix = (uintptr_t)(*x)->interior, iy = (uintptr_t)(*y)->interior;
	if (ix != iy)
		return ix < iy ? -1 : 1;
	return (*x)->id < (*y)->id ? -1 : (*x)->id > (*y)->id;
}

/* Within one object, the leaves that share an interior are all hollow or
 * all solid, as the last of them says (measured in POV-Ray 3.7: in
 * union { sphere { A hollow } sphere { B } } fog stops inside both spheres,
 * and with the hollow one last it shows in both, even under the union's
 * `hollow off`; a leaf with an interior of its own keeps its own flag).
 * Needs the leaves numbered (number_leaves) and their interiors filled. */
static void same_hollow(struct object *o)
{
	if (!o->ops->children)
		return;
	struct objlist l = {0};
	collect_leaves(o, &l);
	qsort(l.v, l.n, sizeof *l.v, by_interior);
	for (size_t i = 0; i < l.n;) {
		size_t j = i;
		while (j + 1 < l.n && l.v[j + 1]->interior == l.v[i]->interior)
			j++;
		unsigned hollow = l.v[j]->flags & OBJ_HOLLOW;
		for (; i <= j; i++)
			l.v[i]->flags = (l.v[i]->flags & ~(unsigned)OBJ_HOLLOW) | hollow;
	}
	free(l.v);
}

/* The first leaf of o that contains pt (o itself does), for its interior. */
static const struct object *leaf_at(const struct object *o, vec3 pt)
{
	struct object **kids;
	if (!o->ops->children)
		return o;
	size_t n = o->ops->children((struct object *)o, &kids);
	for (size_t i = 0; i < n; i++)
		if (object_inside(kids[i], pt))
			return leaf_at(kids[i], pt);
	return n ? leaf_at(kids[0], pt) : NULL;
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
	if (p->features & FEAT_FOCAL_BLUR)
		p->lens = lens_new(s);
	/* projected_through objects are intersected by the tracer. */
	for (size_t i = 0; i < s->nlights; i++)
		if (s->lights[i].projected_through)
			object_prepare(s->lights[i].projected_through);
	if (p->features & (FEAT_MEDIA | FEAT_FOG | FEAT_RAINBOW)) {
		/* Interiors are told apart by pointer; the camera starts inside
		 * those of the objects around it (as in POV-Ray, where a camera
		 * inside glass sees through it from within, and a camera inside
		 * an object that is not hollow sees no fog until its rays leave). */
		for (size_t i = 0; i < s->nobjects; i++) {
			struct interior *in = interior_new();
			fill_interior(s->objects[i], in);
			interior_unref(in);
			same_hollow(s->objects[i]);
			struct medium *cm = &p->camera_medium;
			if (object_inside(s->objects[i], s->camera.location) && cm->n < MEDIUM_MAX) {
				const struct object *leaf = leaf_at(s->objects[i], s->camera.location);
				if (leaf && leaf->interior) {
					if (!(leaf->flags & OBJ_HOLLOW))
						cm->solid |= UINT32_C(1) << cm->n;
					cm->in[cm->n++] = leaf->interior;
				}
			}
		}
	}
	p->max_depth = s->gs.max_trace_level;
	p->quality = 9;
	return p;
}

void prepare_quality(struct prepared *p, int q)
{
	p->quality = q;
	if (q < 8)
		p->features &= ~(unsigned)(FEAT_REFLECTION | FEAT_FRESNEL | FEAT_NORMALS);
	/* Below 6 light still filters through transparent objects on its way
	 * to a surface (POV-Ray's shadows do), but no ray is transmitted. */
	if (q < 6)
		p->features &= ~(unsigned)(FEAT_REFRACTION | FEAT_DISPERSION | FEAT_INTERIORS);
	if (q < 5)
		p->features &= ~(unsigned)FEAT_AREA_LIGHTS;
	if (q < 4)
		p->features &= ~(unsigned)FEAT_SHADOWS;
	if (q < 2)
		p->features &= ~(unsigned)(FEAT_PHONG | FEAT_SPECULAR | FEAT_IRID | FEAT_SPOTLIGHTS | FEAT_LIGHT_FADE);
}

void prepared_free(struct prepared *p)
{
	if (!p) return;
	bvh_free(p->bvh);
	lens_free(p->lens);
	free((void *)p->unbounded);
	free(p);
}

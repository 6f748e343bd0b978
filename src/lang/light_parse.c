/* light_parse.c: light_source statements (every light kind and modifier)
 * and light_group. Each grammar function names its production above it.
 * As in POV-Ray 3.7, a transformation moves what the light has at that
 * point (a point_at given after it is taken as written), and a looks_like
 * object is put at the light's location when it is read, then moves with
 * the light's later transformations. */
#include "lang/parser.h"

#include "geom/csg.h"
#include "scene/light.h"

#include <stdlib.h>
#include <string.h>

void parse_free_light(void *x)
{
	light_free_parts(x);
	free(x);
}

static void free_object_cb(void *o) { object_free(o); }

/* '{' OBJECT '}' after looks_like or projected_through. */
static struct object *parse_light_object(struct parser *p, const char *what)
{
	parse_expect(p, TOK_LBRACE);
	const struct token *t = parse_peek(p);
	if (t->kind == TOK_KEYWORD && parse_is_object_start((enum kw)t->kw)) {
		struct object *o = parse_object(p, false);
		int slot = parse_own(p, o, free_object_cb);
		parse_expect(p, TOK_RBRACE);
		parse_release(p, slot);
		return o;
	}
	const struct value *v = parse_ident_value(p);
	if (!v) {
		char msg[64];
		snprintf(msg, sizeof msg, "an object in %s", what);
		parse_expected(p, msg);
	}
	if (v->kind != VAL_OBJECT)
		parse_wrong_kind(p, v, "an object");
	struct object *o = object_copy(v->obj);
	int slot = parse_own(p, o, free_object_cb);
	parse_advance(p);
	parse_expect(p, TOK_RBRACE);
	parse_release(p, slot);
	return o;
}

/* An optional boolean after a keyword (media_interaction [BOOL]). */
static bool parse_opt_bool(struct parser *p)
{
	if (!parse_starts_expression(p))
		return true;
	return parse_truthy(parse_float(p));
}

/* The cone items of spotlights and cylinder lights: POV-Ray refuses them
 * (and point_at, but for parallel lights) on a plain point light. */
static void need_cone(struct parser *p, const struct light *l, const struct token *kw, bool point_at)
{
	if (l->kind != LIGHT_POINT || (point_at && l->parallel))
		return;
	parse_error_at(p, kw->pos, "%s needs spotlight or cylinder before it%s", kw_names[kw->kw],
	               point_at ? " (or parallel)" : "");
}

/* light_source := light_source '{' ( LIGHT_IDENT | VECTOR [','] COLOR )
 *                 { light_item } '}'
 * light_item := spotlight | cylinder | parallel | shadowless
 *   | radius F | falloff F | tightness F | point_at V
 *   | area_light V ',' V ',' F ',' F | adaptive F | jitter | circular | orient
 *   | area_illumination [BOOL]
 *   | fade_distance F | fade_power F
 *   | media_interaction [BOOL] | media_attenuation [BOOL]
 *   | looks_like '{' OBJECT '}' | projected_through '{' OBJECT '}'
 *   | transform_item
 * Reads into *l, which the caller owns (with its objects) and protects. */
void parse_light(struct parser *p, struct light *l)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	*l = light_default();
	l->srcpos = at;
	const struct value *v = parse_ident_value(p);
	/* Cone sizes the statement gave, so that spotlight and cylinder supply
	 * their own defaults for the rest. */
	bool given_radius = false, given_falloff = false, given_tight = false;
	if (v && v->kind == VAL_LIGHT) {
		*l = *v->light;
		light_copy_parts(l);
		l->srcpos = at;
		given_radius = given_falloff = given_tight = true;
		parse_advance(p);
	} else {
		l->pos = parse_vector(p);
		parse_accept(p, TOK_COMMA);
		l->color = rgb_of(parse_color(p));
	}
	struct srcpos orient_at = at;
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		if (parse_transform_item(p, &t)) {
			light_transform(l, &t);
			continue;
		}
		const struct token *tk = parse_peek(p);
		if (tk->kind != TOK_KEYWORD)
			parse_expected(p, "a light_source item or '}'");
		struct token kw = *tk;
		switch ((enum kw)kw.kw) {
		case KW_SPOTLIGHT:
			parse_advance(p);
			l->kind = LIGHT_SPOT;
			if (!given_radius) l->radius = 30;
			if (!given_falloff) l->falloff = 45;
			if (!given_tight) l->tightness = 0;
			break;
		case KW_CYLINDER:
			parse_advance(p);
			l->kind = LIGHT_CYLINDER;
			if (!given_radius) l->radius = 0.75;
			if (!given_falloff) l->falloff = 1;
			if (!given_tight) l->tightness = 0;
			break;
		case KW_PARALLEL: parse_advance(p); l->parallel = true; break;
		case KW_SHADOWLESS: parse_advance(p); l->shadowless = true; break;
		case KW_RADIUS:
			parse_advance(p);
			need_cone(p, l, &kw, false);
			l->radius = parse_float(p);
			given_radius = true;
			break;
		case KW_FALLOFF:
			parse_advance(p);
			need_cone(p, l, &kw, false);
			l->falloff = parse_float(p);
			given_falloff = true;
			break;
		case KW_TIGHTNESS:
			parse_advance(p);
			need_cone(p, l, &kw, false);
			l->tightness = parse_float(p);
			given_tight = true;
			break;
		case KW_POINT_AT:
			parse_advance(p);
			need_cone(p, l, &kw, true);
			l->point_at = parse_vector(p);
			break;
		case KW_AREA_LIGHT: {
			parse_advance(p);
			l->area = true;
			l->axis1 = parse_vector(p);
			parse_expect(p, TOK_COMMA);
			l->axis2 = parse_vector(p);
			parse_expect(p, TOK_COMMA);
			struct srcpos s1 = parse_peek(p)->pos;
			double n1 = parse_float(p);
			parse_expect(p, TOK_COMMA);
			struct srcpos s2 = parse_peek(p)->pos;
			double n2 = parse_float(p);
			/* POV-Ray truncates the sizes and refuses those below 1. */
			if (!(n1 >= 1))
				parse_error_at(p, s1, "area_light sizes must be at least 1, not %g", n1);
			if (!(n2 >= 1))
				parse_error_at(p, s2, "area_light sizes must be at least 1, not %g", n2);
			if (n1 > 1e6 || n2 > 1e6 || n1 * n2 > 1e6)
				parse_error_at(p, s1, "area_light has too many samples (%g x %g; at most 1000000)", n1, n2);
			l->size1 = (int)n1;
			l->size2 = (int)n2;
			break;
		}
		case KW_ADAPTIVE: {
			parse_advance(p);
			double a = parse_float(p);
			/* POV-Ray takes an integer and treats a negative one as 0. */
			l->adaptive = a < 0 ? 0 : a > 30 ? 30 : (int)a;
			break;
		}
		case KW_JITTER: parse_advance(p); l->jitter = true; break;
		case KW_CIRCULAR: parse_advance(p); l->circular = true; break;
		case KW_ORIENT: parse_advance(p); l->orient = true; orient_at = kw.pos; break;
		case KW_AREA_ILLUMINATION: parse_advance(p); l->area_illumination = parse_opt_bool(p); break;
		case KW_FADE_DISTANCE: parse_advance(p); l->fade_distance = parse_float(p); break;
		case KW_FADE_POWER: parse_advance(p); l->fade_power = parse_float(p); break;
		case KW_MEDIA_INTERACTION: parse_advance(p); l->media_interaction = parse_opt_bool(p); break;
		case KW_MEDIA_ATTENUATION: parse_advance(p); l->media_attenuation = parse_opt_bool(p); break;
		case KW_LOOKS_LIKE: {
			parse_advance(p);
			struct object *o = parse_light_object(p, "looks_like");
			struct xform to = xform_translate(l->pos);
			object_transform(o, &to);
			object_transform_textures(o, &to);
			object_free(l->looks_like);
			l->looks_like = o;
			break;
		}
		case KW_PROJECTED_THROUGH: {
			parse_advance(p);
			struct object *o = parse_light_object(p, "projected_through");
			object_free(l->projected_through);
			l->projected_through = o;
			break;
		}
		default:
			parse_expected(p, "a light_source item or '}'");
		}
	}
	if (l->area && l->orient) {
		/* POV-Ray's corrections, with its warnings. */
		if (!l->circular) {
			parse_warning_at(p, orient_at, "orient can only be used with circular area lights; "
			                               "this area light is now circular");
			l->circular = true;
		}
		double a = v3_len(l->axis1), b = v3_len(l->axis2);
		if (a != b) {
			parse_warning_at(p, orient_at, "with orient, the two axes of the area light must be of equal "
			                               "length; only the length of the first axis is used");
			if (b > 0)
				l->axis2 = v3_scale(l->axis2, a / b);
		}
		if (l->size1 != l->size2)
			parse_warning_at(p, orient_at, "with orient, the two sample sizes of the area light should be equal");
	}
}

/* Put a light's looks_like object into the scene (or the group being
 * read, `into`): it never casts shadows, so the light inside it shines
 * out, as in POV-Ray. */
static void place_looks_like(struct parser *p, struct light *l, struct object *into)
{
	struct object *o = l->looks_like;
	if (!o)
		return;
	l->looks_like = NULL;
	object_set_flags(o, OBJ_NO_SHADOW);
	if (into) {
		csg_add(into, o);
		return;
	}
	if (p->default_tex)
		object_fill_texture(o, p->default_tex);
	scene_add_object(p->scene, o);
}

void parse_light_statement(struct parser *p)
{
	struct light *l = malloc(sizeof *l);
	if (!l) abort();
	memset(l, 0, sizeof *l);
	int slot = parse_own(p, l, parse_free_light);
	parse_light(p, l);
	place_looks_like(p, l, NULL);
	scene_add_light(p->scene, l);
	parse_release(p, slot);
	free(l); /* its objects now belong to the scene */
}

/* ---- light groups ---- */

/* A light_group being read. */
struct group_ctx {
	int self;         /* its number */
	int start;        /* groups numbered from here on were made inside it */
	size_t first_light; /* lights from here on belong to it or its nested groups */
	int (*map)[2];    /* declared groups placed here: old number -> new */
	int nmap, capmap;
};

static void free_map_cb(void *x)
{
	free(x);
}

/* The group that stands for the declared group `old` inside this one: a
 * new group, under the new copy of old's parent (or this group), with
 * copies of old's lights, so that transformations of this statement move
 * them and nothing else does. */
static int remap_group(struct parser *p, struct group_ctx *c, int *mslot, int old)
{
	if (old == 0)
		return c->self;
	for (int i = 0; i < c->nmap; i++)
		if (c->map[i][0] == old)
			return c->map[i][1];
	struct scene *s = p->scene;
	int parent = remap_group(p, c, mslot, s->groups[old].parent);
	int n = scene_add_light_group(s, parent);
	s->groups[n].global_lights = s->groups[old].global_lights;
	if (c->nmap == c->capmap) {
		c->capmap = c->capmap ? 2 * c->capmap : 8;
		c->map = realloc(c->map, (size_t)c->capmap * sizeof *c->map);
		if (!c->map) abort();
		p->owned[*mslot].ptr = c->map;
	}
	c->map[c->nmap][0] = old;
	c->map[c->nmap][1] = n;
	c->nmap++;
	size_t nl = s->nlights;
	for (size_t i = 0; i < nl; i++) {
		if (s->lights[i].group != old)
			continue;
		struct light copy = s->lights[i];
		light_copy_parts(&copy);
		copy.group = n;
		scene_add_light(s, &copy);
	}
	return n;
}

/* A new carrier group holding copies of the lights of carrier `old` (the
 * lights of a declared CSG being placed). */
static int copy_carrier(struct scene *s, int old)
{
	int n = scene_add_light_group(s, 0);
	s->groups[n].carrier = true;
	size_t nl = s->nlights;
	for (size_t i = 0; i < nl; i++) {
		if (s->lights[i].group != old)
			continue;
		struct light copy = s->lights[i];
		light_copy_parts(&copy);
		copy.group = n;
		scene_add_light(s, &copy);
	}
	return n;
}

/* Give the leaves of o (just read into the group) their group: this one
 * for leaves outside any group; the groups made inside this statement are
 * put under it; a declared group placed here gets a copy of its own. */
static void tag_leaves(struct parser *p, struct group_ctx *c, int *mslot, struct object *o)
{
	struct object **kids;
	if (o->carried_lights != 0 && o->carried_lights < c->start)
		o->carried_lights = copy_carrier(p->scene, o->carried_lights);
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			tag_leaves(p, c, mslot, kids[i]);
		return;
	}
	struct light_group *gs = p->scene->groups;
	int g = o->light_group;
	if (g == 0) {
		o->light_group = c->self;
	} else if (g >= c->start) {
		while (g != c->self && gs[g].parent != 0)
			g = gs[g].parent;
		if (g != c->self)
			gs[g].parent = c->self;
	} else {
		o->light_group = remap_group(p, c, mslot, g);
	}
}

/* Give the leaves of o, the copy of a declared object being placed, their
 * own copies of the light groups they are in (with copies of the groups'
 * lights), and its CSGs their own copies of the lights they carry, so that
 * the transformations of this placement move those lights and no other
 * placement shares them: POV-Ray copies a group's lights with the object. */
static void remap_leaves(struct parser *p, struct group_ctx *c, int *mslot, struct object *o)
{
	struct object **kids;
	if (o->carried_lights != 0)
		o->carried_lights = copy_carrier(p->scene, o->carried_lights);
	if (o->ops->children) {
		size_t n = o->ops->children(o, &kids);
		for (size_t i = 0; i < n; i++)
			remap_leaves(p, c, mslot, kids[i]);
		return;
	}
	if (o->light_group != 0)
		o->light_group = remap_group(p, c, mslot, o->light_group);
}

void parse_place_light_groups(struct parser *p, struct object *o)
{
	if (p->scene->ngroups <= 1)
		return;
	struct group_ctx c = {0};
	c.capmap = 8;
	c.map = malloc((size_t)c.capmap * sizeof *c.map);
	if (!c.map) abort();
	int mslot = parse_own(p, c.map, free_map_cb);
	remap_leaves(p, &c, &mslot, o);
	parse_release(p, mslot);
	free(c.map);
}

/* csg_light := light_source '{' ... '}'   (in the body of a CSG)
 * POV-Ray 3.7 (measured): the light lights the whole scene, as a global
 * light even inside a light_group; the CSG's later transformations move
 * it; it is copied with the CSG and shines only where the CSG is placed
 * (a declared CSG that is never placed gives no light). It is no part of
 * the solid, but its looks_like object is one of the CSG's children. */
void parse_csg_light(struct parser *p, struct object *csg)
{
	struct scene *s = p->scene;
	struct light *l = malloc(sizeof *l);
	if (!l) abort();
	memset(l, 0, sizeof *l);
	int slot = parse_own(p, l, parse_free_light);
	parse_light(p, l);
	if (csg->carried_lights == 0) {
		csg->carried_lights = scene_add_light_group(s, 0);
		s->groups[csg->carried_lights].carrier = true;
	}
	l->group = csg->carried_lights;
	place_looks_like(p, l, csg);
	scene_add_light(s, l);
	parse_release(p, slot);
	free(l);
}

void parse_move_lights(struct parser *p, size_t from, const struct xform *t)
{
	for (size_t i = from; i < p->scene->nlights; i++)
		light_transform(&p->scene->lights[i], t);
}

/* light_group := light_group '{' { OBJECT | light_source | transform_item
 *                | global_lights [BOOL] } '}'
 * A union of its objects, lit by its own lights (and those of the groups
 * it is in), and by the scene's other lights only with global_lights. The
 * lights go into the scene now; they light nothing outside the group. */
struct object *parse_light_group(struct parser *p, bool child)
{
	struct srcpos at = parse_peek(p)->pos;
	parse_advance(p);
	parse_expect(p, TOK_LBRACE);
	struct scene *s = p->scene;
	struct group_ctx c = {0};
	c.self = scene_add_light_group(s, 0);
	c.start = c.self;
	c.first_light = s->nlights;
	struct object *u = csg_new(CSG_UNION, at);
	int slot = parse_own(p, u, free_object_cb);
	c.capmap = 8;
	c.map = malloc((size_t)c.capmap * sizeof *c.map);
	if (!c.map) abort();
	int mslot = parse_own(p, c.map, free_map_cb);
	while (!parse_accept(p, TOK_RBRACE)) {
		struct xform t;
		if (parse_transform_item(p, &t)) {
			object_transform(u, &t);
			object_transform_textures(u, &t);
			parse_move_lights(p, c.first_light, &t);
			continue;
		}
		const struct token *tk = parse_peek(p);
		if (tk->kind == TOK_KEYWORD && tk->kw == KW_LIGHT_SOURCE) {
			struct light *l = malloc(sizeof *l);
			if (!l) abort();
			memset(l, 0, sizeof *l);
			int ls = parse_own(p, l, parse_free_light);
			parse_light(p, l);
			l->group = c.self;
			if (l->looks_like) {
				struct object *o = l->looks_like;
				place_looks_like(p, l, u);
				tag_leaves(p, &c, &mslot, o);
			}
			scene_add_light(s, l);
			parse_release(p, ls);
			free(l);
			continue;
		}
		if (parse_accept_kw(p, KW_GLOBAL_LIGHTS)) {
			s->groups[c.self].global_lights = parse_opt_bool(p);
			continue;
		}
		if (tk->kind == TOK_KEYWORD && parse_is_object_start((enum kw)tk->kw)) {
			struct object *o = parse_object(p, false);
			csg_add(u, o);
			tag_leaves(p, &c, &mslot, o);
			continue;
		}
		const struct value *v = parse_ident_value(p);
		if (v && v->kind == VAL_OBJECT) {
			/* light_group { OBJECT_IDENTIFIER } */
			struct object *o = object_copy(v->obj);
			parse_advance(p);
			csg_add(u, o);
			tag_leaves(p, &c, &mslot, o);
			continue;
		}
		parse_expected(p, "an object, light_source, global_lights, a transformation or '}'");
	}
	parse_release(p, mslot);
	free(c.map);
	if (!child && p->default_tex)
		object_fill_texture(u, p->default_tex);
	parse_release(p, slot);
	return u;
}

/* texture.c: construction, sharing and copying of pigments, normals,
 * finishes, interiors, maps and textures (see texture.h). Evaluation is in
 * texture_eval.c. */
#include "scene/texture.h"

#include <stdlib.h>
#include <string.h>

static void *xcalloc(size_t n, size_t size)
{
	void *p = calloc(n ? n : 1, size);
	if (!p) abort();
	return p;
}

/* ---- maps ---- */

struct blend_map *blend_map_new(enum map_kind kind, int n)
{
	struct blend_map *m = xcalloc(1, sizeof *m);
	m->refs = 1;
	m->kind = kind;
	m->n = n;
	m->e = xcalloc((size_t)n, sizeof *m->e);
	return m;
}

struct blend_map *blend_map_ref(struct blend_map *m)
{
	if (m)
		m->refs++;
	return m;
}

void blend_map_unref(struct blend_map *m)
{
	if (!m || --m->refs > 0)
		return;
	for (int i = 0; i < m->n; i++) {
		void *it = m->e[i].item;
		if (!it)
			continue;
		switch (m->kind) {
		case MAP_PIGMENT: pigment_unref(it); break;
		case MAP_NORMAL: normal_unref(it); break;
		case MAP_TEXTURE: texture_unref(it); break;
		default: break;
		}
	}
	free(m->e);
	free(m);
}

void blend_map_find(const struct blend_map *m, double v, int *lo, int *hi, double *w)
{
	int n = m->n;
	if (n <= 1 || v <= m->e[0].value) {
		*lo = *hi = 0;
		*w = 0;
		return;
	}
	if (v >= m->e[n - 1].value) {
		*lo = *hi = n - 1;
		*w = 0;
		return;
	}
	int i = 1;
	while (i < n - 1 && m->e[i].value < v)
		i++;
	/* e[i-1].value < v <= e[i].value */
	double a = m->e[i - 1].value, b = m->e[i].value;
	*lo = i - 1;
	*hi = i;
	*w = b > a ? (v - a) / (b - a) : 1.0;
}

/* ---- pigment ---- */

/* Parsing makes a pigment and a texture for nearly every object, so they
 * are copied whole from templates (static storage: padding zero too, as
 * calloc's) instead of zeroed and filled field by field. */
static void *xmalloc(size_t size)
{
	void *p = malloc(size);
	if (!p) abort();
	return p;
}

struct pigment *pigment_new(void)
{
	static const struct pigment tmpl = {.refs = 1, .kind = PIGMENT_SOLID, .pat = PATTERN_INIT_NONE};
	struct pigment *p = xmalloc(sizeof *p);
	*p = tmpl;
	return p;
}

struct pigment *pigment_ref(struct pigment *p)
{
	if (p)
		p->refs++;
	return p;
}

void pigment_unref(struct pigment *p)
{
	if (!p || --p->refs > 0)
		return;
	pattern_clear(&p->pat);
	blend_map_unref(p->map);
	free(p);
}

struct pigment *pigment_copy(const struct pigment *p)
{
	struct pigment *c = xcalloc(1, sizeof *c);
	*c = *p;
	c->refs = 1;
	c->pat = pattern_copy(&p->pat);
	c->map = blend_map_ref(p->map);
	return c;
}

/* ---- normal ---- */

struct normal *normal_new(enum pattern_kind k)
{
	struct normal *n = xcalloc(1, sizeof *n);
	n->refs = 1;
	n->pat = pattern_make(k);
	n->amount = 0.5;
	n->accuracy = 0.02;
	return n;
}

struct normal *normal_ref(struct normal *n)
{
	if (n)
		n->refs++;
	return n;
}

void normal_unref(struct normal *n)
{
	if (!n || --n->refs > 0)
		return;
	pattern_clear(&n->pat);
	blend_map_unref(n->map);
	free(n);
}

struct normal *normal_copy(const struct normal *n)
{
	struct normal *c = xcalloc(1, sizeof *c);
	*c = *n;
	c->refs = 1;
	c->pat = pattern_copy(&n->pat);
	c->map = blend_map_ref(n->map);
	return c;
}

/* ---- finish ---- */

/* POV-Ray's finish defaults, the initialiser of finish_default()'s value
 * and of the finish in the texture template. */
#define FINISH_INIT_DEFAULT                                                     \
	{                                                                       \
		.ambient = {0.1, 0.1, 0.1}, .diffuse = 0.6, .brilliance = 1.0,  \
		.phong = 0.0, .phong_size = 40.0, .specular = 0.0,              \
		.roughness = 0.05, .reflection_falloff = 1.0,                   \
		.reflection_exponent = 1.0, .irid_thickness = 0.0,              \
	}

struct finish finish_default(void)
{
	static const struct finish f = FINISH_INIT_DEFAULT;
	return f;
}

/* ---- interior ---- */

struct interior *interior_new(void)
{
	struct interior *i = xcalloc(1, sizeof *i);
	i->refs = 1;
	i->ior = 1.0;
	i->dispersion = 1.0;
	i->dispersion_samples = 7;
	return i;
}

struct interior *interior_ref(struct interior *i)
{
	if (i)
		i->refs++;
	return i;
}

void interior_unref(struct interior *i)
{
	if (i && --i->refs == 0)
		free(i);
}

struct interior *interior_copy(const struct interior *i)
{
	struct interior *c = xcalloc(1, sizeof *c);
	*c = *i;
	c->refs = 1;
	return c;
}

/* ---- texture ---- */

struct texture *texture_new(void)
{
	static const struct texture tmpl = {
		.refs = 1, .kind = TEX_PLAIN, .finish = FINISH_INIT_DEFAULT, .pat = PATTERN_INIT_NONE,
	};
	struct texture *t = xmalloc(sizeof *t);
	*t = tmpl;
	t->pigment = pigment_new();
	return t;
}

struct texture *texture_ref(struct texture *t)
{
	if (t)
		t->refs++;
	return t;
}

void texture_unref(struct texture *t)
{
	while (t && --t->refs == 0) {
		struct texture *next = t->next;
		pigment_unref(t->pigment);
		normal_unref(t->normal);
		pattern_clear(&t->pat);
		blend_map_unref(t->map);
		free(t);
		t = next;
	}
}

struct texture *texture_copy(const struct texture *t)
{
	struct texture *c = xcalloc(1, sizeof *c);
	*c = *t;
	c->refs = 1;
	c->pigment = pigment_ref(t->pigment);
	c->normal = normal_ref(t->normal);
	c->pat = pattern_copy(&t->pat);
	c->map = blend_map_ref(t->map);
	c->next = texture_ref(t->next);
	return c;
}

/* A private copy of the map m (entries re-referenced), replacing *mp. */
static struct blend_map *map_unshare(struct blend_map **mp)
{
	struct blend_map *m = *mp;
	if (m->refs == 1)
		return m;
	struct blend_map *c = blend_map_new(m->kind, m->n);
	memcpy(c->e, m->e, (size_t)m->n * sizeof *m->e);
	for (int i = 0; i < m->n; i++) {
		void *it = m->e[i].item;
		if (!it)
			continue;
		switch (m->kind) {
		case MAP_PIGMENT: pigment_ref(it); break;
		case MAP_NORMAL: normal_ref(it); break;
		case MAP_TEXTURE: texture_ref(it); break;
		default: break;
		}
	}
	blend_map_unref(m);
	*mp = c;
	return c;
}


/* Transform every item of a pigment, normal or texture map (the items'
 * own patterns move with the outer one, as in POV-Ray). */
static void map_transform(struct blend_map **mp, const struct xform *xf)
{
	if (!*mp || (*mp)->kind == MAP_COLOR || (*mp)->kind == MAP_SLOPE)
		return;
	struct blend_map *m = map_unshare(mp);
	for (int i = 0; i < m->n; i++) {
		void *it = m->e[i].item;
		if (!it)
			continue;
		switch (m->kind) {
		case MAP_PIGMENT: m->e[i].item = pigment_transform(it, xf); break;
		case MAP_NORMAL: m->e[i].item = normal_transform(it, xf); break;
		case MAP_TEXTURE: m->e[i].item = texture_transform(it, xf); break;
		default: break;
		}
	}
}

struct pigment *pigment_transform(struct pigment *p, const struct xform *xf)
{
	if (p->kind == PIGMENT_SOLID)
		return p;
	if (p->refs > 1) {
		struct pigment *c = pigment_copy(p);
		pigment_unref(p);
		p = c;
	}
	pattern_transform(&p->pat, xf);
	map_transform(&p->map, xf);
	return p;
}

struct normal *normal_transform(struct normal *n, const struct xform *xf)
{
	if (n->refs > 1) {
		struct normal *c = normal_copy(n);
		normal_unref(n);
		n = c;
	}
	pattern_transform(&n->pat, xf);
	map_transform(&n->map, xf);
	return n;
}

struct texture *texture_transform(struct texture *t, const struct xform *xf)
{
	if (!t)
		return t;
	if (t->refs > 1) {
		struct texture *c = texture_copy(t);
		texture_unref(t);
		t = c;
	}
	if (t->kind == TEX_PLAIN) {
		t->pigment = pigment_transform(t->pigment, xf);
		if (t->normal)
			t->normal = normal_transform(t->normal, xf);
	} else {
		pattern_transform(&t->pat, xf);
		map_transform(&t->map, xf);
	}
	if (t->next)
		t->next = texture_transform(t->next, xf);
	return t;
}

static void pigment_prepare(struct pigment *p);
static void normal_prepare(struct normal *n);

static void map_prepare(struct blend_map *m)
{
	if (!m)
		return;
	for (int i = 0; i < m->n; i++) {
		void *it = m->e[i].item;
		if (!it)
			continue;
		switch (m->kind) {
		case MAP_PIGMENT: pigment_prepare(it); break;
		case MAP_NORMAL: normal_prepare(it); break;
		case MAP_TEXTURE: texture_prepare(it); break;
		default: break;
		}
	}
}

static void pigment_prepare(struct pigment *p)
{
	pattern_prepare(&p->pat);
	map_prepare(p->map);
}

static void normal_prepare(struct normal *n)
{
	pattern_prepare(&n->pat);
	map_prepare(n->map);
}

void texture_prepare(struct texture *t)
{
	for (; t; t = t->next) {
		if (t->pigment)
			pigment_prepare(t->pigment);
		if (t->normal)
			normal_prepare(t->normal);
		pattern_prepare(&t->pat);
		map_prepare(t->map);
	}
}

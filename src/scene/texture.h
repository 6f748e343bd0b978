/* texture.h: what a surface looks like: pigments, normals, finishes, the
 * textures that bundle them (plain, patterned through a texture_map or a
 * block pattern, layered), and interiors.
 *
 * Pigments, normals, textures, interiors and maps are reference-counted:
 * declared once, shared by every object that uses them; whoever modifies
 * one that is shared takes a private copy first (the *_copy functions).
 * The parser builds them, prepare walks them once (features, prepared
 * object patterns), and the tracer evaluates them (texture_eval.c). */
#ifndef LUCENT_TEXTURE_H
#define LUCENT_TEXTURE_H

#include "pattern/pattern.h"
#include "scene/color.h"

#include <stdbool.h>

struct pigment;
struct normal;
struct texture;

/* ---- maps: colour_map, pigment_map, normal_map, slope_map, texture_map ---- */

enum map_kind { MAP_COLOR, MAP_PIGMENT, MAP_NORMAL, MAP_SLOPE, MAP_TEXTURE };

struct map_entry {
	double value;                /* the pattern value of the entry */
	struct rgbft color;          /* MAP_COLOR */
	double slope[2];             /* MAP_SLOPE: height, slope */
	void *item;                  /* MAP_PIGMENT/NORMAL/TEXTURE: one reference (NULL: a hole, as POV-Ray's
	                              * `[v]` with nothing, which is transparent for pigments) */
};

struct blend_map {
	int refs;
	enum map_kind kind;
	int n;
	struct map_entry *e;         /* sorted by value, as written (POV-Ray does not sort) */
};

struct blend_map *blend_map_new(enum map_kind kind, int n);
struct blend_map *blend_map_ref(struct blend_map *m);
void blend_map_unref(struct blend_map *m);
/* The entries around value v and the weight of the second one: the result
 * is (1-w)*e[*lo] + w*e[*hi]. Below the first entry or above the last, both
 * are that entry. */
void blend_map_find(const struct blend_map *m, double v, int *lo, int *hi, double *w);

/* ---- pigment ---- */

enum pigment_kind {
	PIGMENT_SOLID,      /* color */
	PIGMENT_PATTERN,    /* pattern looked up in map (colour or pigment map; NULL: the kind's default map) */
	PIGMENT_IMAGE,      /* image_map: the image's colours through pat.img */
};

struct pigment {
	int refs;
	enum pigment_kind kind;
	struct rgbft color;          /* SOLID: the colour; otherwise quick_color */
	bool quick;                  /* not SOLID: a quick_color was given (shown below +Q6) */
	struct pattern pat;
	struct blend_map *map;       /* one reference, or NULL */
};

struct pigment *pigment_new(void);   /* solid black, one reference */
struct pigment *pigment_ref(struct pigment *p);
void pigment_unref(struct pigment *p);
struct pigment *pigment_copy(const struct pigment *p);   /* a private deep copy */

/* ---- normal ---- */

struct normal {
	int refs;
	struct pattern pat;          /* bumps, dents, ..., or any pattern (its slope), or a block pattern of normals */
	double amount;               /* bump_size, or the float after the pattern (default 0.5 for most) */
	double accuracy;             /* 0.02: the step of the numerical slope */
	struct blend_map *map;       /* normal_map, slope_map, or the block pattern's normals; one reference or NULL */
};

struct normal *normal_new(enum pattern_kind k);
struct normal *normal_ref(struct normal *n);
void normal_unref(struct normal *n);
struct normal *normal_copy(const struct normal *n);

/* ---- finish ---- */

/* How light leaves the surface (POV-Ray's defaults in finish_default()). */
struct finish {
	rgb ambient;                 /* multiplied by the pigment and global ambient_light */
	rgb emission;                /* multiplied by the pigment, regardless of lights */
	double diffuse;              /* front side */
	double diffuse_back;         /* the second value of `diffuse a, b`: light from behind */
	double brilliance;
	double crand;
	double phong, phong_size;
	double specular, roughness;
	double metallic;             /* 0: highlights in the light's colour; 1: the surface's */
	/* reflection: a colour, or the block form */
	rgb reflection_min;          /* at normal incidence / the plain colour */
	rgb reflection_max;          /* at grazing incidence (the block form's second colour) */
	bool reflection_fresnel;
	double reflection_falloff;   /* 1 */
	double reflection_exponent;  /* 1 */
	double reflection_metallic;  /* 0 */
	bool conserve_energy;
	double irid, irid_thickness, irid_turbulence;
	/* The pre-3.1 places of interior items, accepted with a warning as
	 * POV-Ray does: 0 when not given; prepare moves them into the
	 * interior of objects that have none of their own. */
	double legacy_ior, legacy_caustics;
};

struct finish finish_default(void);

/* ---- interior ---- */

struct interior {
	int refs;
	double ior;                  /* 1 */
	bool ior_given;              /* ior written out (see interior_dispersion) */
	double caustics;             /* 0 */
	double dispersion;           /* 1 */
	int dispersion_samples;      /* 7 */
	double fade_distance;        /* 0: no fading */
	double fade_power;           /* 0 */
	rgb fade_color;              /* black */
};

struct interior *interior_new(void);
struct interior *interior_ref(struct interior *i);
void interior_unref(struct interior *i);
struct interior *interior_copy(const struct interior *i);

/* The dispersion that applies in interior i: POV-Ray 3.7 disperses only
 * where the interior's ior is written out, even as `ior 1` (measured:
 * `interior { dispersion 1.3 }` alone, or with a pre-3.1 `finish { ior }`,
 * renders as if without dispersion). */
static inline double interior_dispersion(const struct interior *i)
{
	return i->ior_given ? i->dispersion : 1.0;
}

/* ---- texture ---- */

enum texture_kind {
	TEX_PLAIN,       /* pigment, normal, finish */
	TEX_PATTERNED,   /* pat looked up in map (entries are textures): texture_map, block patterns */
	TEX_MATERIAL,    /* material_map: pat is PAT_IMAGE, the palette index picks map->e[i].item */
};

struct texture {
	int refs;
	enum texture_kind kind;
	struct pigment *pigment;     /* PLAIN: one reference (never NULL) */
	struct normal *normal;       /* PLAIN: one reference or NULL (no perturbation) */
	struct finish finish;        /* PLAIN */
	struct pattern pat;          /* PATTERNED, MATERIAL */
	struct blend_map *map;       /* PATTERNED, MATERIAL: MAP_TEXTURE */
	struct texture *next;        /* layered textures: the layer under this one (one reference), or NULL */
	bool uv_mapped;              /* texture { uv_mapping }: layered on as if patterned (texture_is_patterned) */
};

/* Does POV-Ray 3.7 count the top layer of t as patterned, so that nothing
 * can be layered over it (texture, pigment, normal or finish) and it over
 * nothing? Block patterns, texture and material maps, and a texture-level
 * uv_mapping (measured: `texture { uv_mapping pigment { rgb 1 } }` then
 * `finish { }` is POV-Ray's "Cannot layer over a patterned texture"). */
static inline bool texture_is_patterned(const struct texture *t)
{
	return t->kind != TEX_PLAIN || t->uv_mapped;
}

/* A new plain texture with POV-Ray's defaults (black pigment, default
 * finish), holding one reference. */
struct texture *texture_new(void);
struct texture *texture_ref(struct texture *t);
void texture_unref(struct texture *t);
/* A private copy (one reference) of t, for modification: the top layer is
 * copied, what it refers to is shared. */
struct texture *texture_copy(const struct texture *t);
/* Apply a transformation to every pattern in t (the object's transform
 * reaching its texture), copying what is shared. Returns t or its copy;
 * the reference to t passes to the result. */
struct texture *texture_transform(struct texture *t, const struct xform *xf);
/* The same for a pigment and a normal (their patterns and map items);
 * the reference passes to the result. */
struct pigment *pigment_transform(struct pigment *p, const struct xform *xf);
struct normal *normal_transform(struct normal *n, const struct xform *xf);
/* Prepare every pattern in t (object patterns' bounds). */
void texture_prepare(struct texture *t);

/* ---- evaluation (texture_eval.c) ---- */

/* Entry i of the colour list a block pattern of kind k uses where the
 * scene gives none (or gives fewer entries than the pattern takes). */
struct rgbft pattern_block_default(enum pattern_kind k, int i);
/* The pigment's colour at ctx. */
struct rgbft pigment_eval(const struct pigment *pg, const struct pattern_ctx *ctx);
/* The height whose slope tilts a normal, for a value v of nm's pattern:
 * v through nm's slope_map if it has one. */
double normal_height(const struct normal *nm, double v);
/* The normal n (unit, world space) perturbed by nm at ctx; unit. */
vec3 normal_eval(const struct normal *nm, vec3 n, const struct pattern_ctx *ctx);

#endif

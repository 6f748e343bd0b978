/* value.h: the values a scene program computes and identifiers hold:
 * numbers, vectors and colours (up to five components), strings, and
 * scene items (objects, textures, pigments, finishes). Scene items are
 * owned by the value: copying a value copies or references them. */
#ifndef LUCENT_VALUE_H
#define LUCENT_VALUE_H

#include "lang/source.h"
#include "scene/object.h"
#include "scene/texture.h"

#include <stdio.h>

enum val_kind {
	VAL_NONE,
	VAL_FLOAT,
	VAL_VECTOR,   /* n = 2..5 components */
	VAL_COLOR,    /* 5 components: r g b filter transmit */
	VAL_STRING,   /* interned, never freed separately */
	VAL_OBJECT,
	VAL_TEXTURE,
	VAL_PIGMENT,
	VAL_FINISH,
	VAL_NORMAL,
	VAL_INTERIOR,
	VAL_MATERIAL, /* a texture and an interior */
	VAL_MAP,      /* color_map, pigment_map, normal_map, slope_map, texture_map (map->kind tells) */
	VAL_CAMERA,
	VAL_LIGHT,
	VAL_TRANSFORM,
	VAL_MACRO,    /* a #macro definition (shared, reference-counted) */
	VAL_ALIAS,    /* a by-reference macro parameter: names another binding */
	VAL_ARRAY,    /* shared, reference-counted, copied on write */
	VAL_SPLINE,   /* shared, reference-counted */
	VAL_FUNCTION, /* a compiled user function (shared, reference-counted) */
	VAL_FILE,     /* an #fopen'ed file */
	VAL_FOG,      /* fog { } (owned copy) */
	VAL_SKY_SPHERE, /* sky_sphere { } (owned) */
	VAL_RAINBOW,  /* rainbow { } (owned; holds its colour map's reference) */
};

struct light;
struct camera;
struct fog;
struct sky_sphere;
struct rainbow;

/* material { texture interior }: what a material identifier holds. */
struct material {
	struct texture *tex;         /* one reference, or NULL */
	struct interior *interior;   /* one reference, or NULL */
};
struct symtab;

/* A macro: its parameters and where its body lies in a file's tokens. */
struct macro {
	int refs;
	const char *name;        /* interned */
	struct srcpos pos;       /* of the #macro */
	uint32_t file;           /* the file whose tokens hold the body */
	size_t body, end;        /* token indices: first body token, the '#' of #end */
	int nparams;
	const char **params;     /* interned names */
};

/* An array of up to 5 dimensions; elements of kind VAL_NONE are not yet
 * initialised. Shared between values by reference count; a write to a
 * shared array copies it first. */
enum { ARRAY_MAX_DIMS = 5 };
struct array {
	int refs;
	int ndims;
	int dims[ARRAY_MAX_DIMS];
	size_t count;
	struct value *elems;
};

enum spline_kind { SPLINE_LINEAR, SPLINE_QUADRATIC, SPLINE_CUBIC, SPLINE_NATURAL };

/* A spline: control points (t, value) sorted by t. */
struct spline {
	int refs;
	enum spline_kind kind;
	int n;             /* control points */
	int dim;           /* components of the values (1..5) */
	double *t;         /* n parameters */
	double *v;         /* n*5 components */
	double *d2;        /* NATURAL: second derivatives, n*5 */
};

struct fn;

/* A file opened by #fopen. */
struct sdl_file {
	int refs;
	FILE *fp;
	bool writing;
	const char *name;        /* interned, as written in #fopen */
	const struct token *toks; /* reading: the file lexed, with its position */
	size_t ntoks, pos;
	bool borrowed_toks;       /* the tokens belong to the source manager */
};

/* Where a by-reference parameter's value really lives. */
struct alias {
	struct symtab *table;
	const char *name;
	size_t index;      /* an element of the array `name`, or ALIAS_WHOLE */
};
#define ALIAS_WHOLE ((size_t)-1)
struct value {
	enum val_kind kind;
	int n;                 /* components for FLOAT (1), VECTOR, COLOR (5) */
	int owner;             /* > 0: held in the parser's ownership slot owner-1
	                        * while an expression is being evaluated */
	const char *deprecated; /* #declare deprecated: the warning to give on use */
	bool deprecated_once;  /* warn only the first time */
	struct srcpos pos;
	union {
		double v[5];
		const char *str;
		struct object *obj;    /* owned */
		struct texture *tex;   /* one reference */
		struct pigment *pig;   /* one reference */
		struct finish *fin;    /* owned */
		struct normal *nrm;    /* one reference */
		struct interior *interior; /* one reference */
		struct material *mat;  /* owned */
		struct blend_map *map; /* one reference */
		struct camera *cam;    /* owned */
		struct light *light;   /* owned */
		struct xform *xf;      /* owned */
		struct macro *mac;     /* one reference */
		struct alias alias;
		struct array *arr;     /* one reference */
		struct spline *spl;    /* one reference */
		struct fn *fn;         /* one reference */
		struct sdl_file *file; /* one reference */
		struct fog *fog;       /* owned */
		struct sky_sphere *sky; /* owned */
		struct rainbow *rainbow; /* owned */
	};
};

/* A description of a kind for messages ("float", "vector", "object"). */
const char *val_kind_name(enum val_kind k);
/* Release what v owns; v becomes VAL_NONE. */
void val_clear(struct value *v);
/* A deep copy of src (objects copied, textures referenced). */
struct value val_copy(const struct value *src);
static inline bool val_is_numeric(const struct value *v)
{
	return v->kind == VAL_FLOAT || v->kind == VAL_VECTOR || v->kind == VAL_COLOR;
}

static inline struct value val_float(double x, struct srcpos pos)
{
	struct value v = {.kind = VAL_FLOAT, .n = 1, .pos = pos};
	v.v[0] = x;
	return v;
}

/* A vector (kind VAL_VECTOR) or colour (VAL_COLOR, always 5 components)
 * from n components; the rest are 0. */
static inline struct value val_vector(int n, const double *c, enum val_kind kind, struct srcpos pos)
{
	struct value v = {.kind = kind, .n = kind == VAL_COLOR ? 5 : n, .pos = pos};
	for (int i = 0; i < 5; i++)
		v.v[i] = i < n ? c[i] : 0;
	return v;
}

/* Promote a to n components: a float fills every component, a vector is
 * padded with zeros (POV-Ray's rules). */
static inline void val_widen(struct value *a, int n)
{
	if (a->n >= n)
		return;
	for (int i = a->n; i < n; i++)
		a->v[i] = a->kind == VAL_FLOAT ? a->v[0] : 0;
	a->n = n;
}

/* A new array with the given dimensions, all elements uninitialised. */
struct array *array_new(int ndims, const int *dims);
/* The array of v made unshared (copied if others hold it). */
struct array *array_unshare(struct value *v);
void spline_unref(struct spline *s);
void sdl_file_unref(struct sdl_file *f);

#endif

/* value.h: the values a scene program computes and identifiers hold:
 * numbers, vectors and colours (up to five components), strings, and
 * scene items (objects, textures, pigments, finishes). Scene items are
 * owned by the value: copying a value copies or references them. */
#ifndef LUCENT_VALUE_H
#define LUCENT_VALUE_H

#include "lang/source.h"
#include "scene/object.h"
#include "scene/texture.h"

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
	VAL_CAMERA,
	VAL_LIGHT,
	VAL_TRANSFORM,
	VAL_MACRO,    /* a #macro definition (shared, reference-counted) */
	VAL_ALIAS,    /* a by-reference macro parameter: names another binding */
};

struct light;
struct camera;
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

/* Where a by-reference parameter's value really lives. */
struct alias {
	struct symtab *table;
	const char *name;
};
struct value {
	enum val_kind kind;
	int n;                 /* components for FLOAT (1), VECTOR, COLOR (5) */
	int owner;             /* > 0: held in the parser's ownership slot owner-1
	                        * while an expression is being evaluated */
	struct srcpos pos;
	union {
		double v[5];
		const char *str;
		struct object *obj;    /* owned */
		struct texture *tex;   /* one reference */
		struct pigment *pig;   /* owned */
		struct finish *fin;    /* owned */
		struct camera *cam;    /* owned */
		struct light *light;   /* owned */
		struct xform *xf;      /* owned */
		struct macro *mac;     /* one reference */
		struct alias alias;
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

#endif

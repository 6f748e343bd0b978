/* texture.h: the surface description the parser builds and the shader
 * reads: pigment, finish, and the texture that bundles them. Textures are
 * reference-counted: declared once, shared by every object that uses them. */
#ifndef LUCENT_TEXTURE_H
#define LUCENT_TEXTURE_H

#include "scene/color.h"

#include <stdbool.h>

enum pigment_kind {
	PIGMENT_SOLID, /* one colour */
};

struct pigment {
	enum pigment_kind kind;
	struct rgbft color;
};

/* The finish: how light leaves the surface (POV-Ray's defaults in
 * finish_default()). */
struct finish {
	rgb ambient;       /* multiplied by the pigment and global ambient_light */
	rgb emission;      /* added regardless of lights */
	double diffuse;
	double brilliance;
	double phong, phong_size;
	double specular, roughness;
	rgb reflection;    /* constant mirror reflection */
	bool metallic;
};

struct texture {
	int refs;
	struct pigment pigment;
	struct finish finish;
};

struct finish finish_default(void);
/* A new texture with POV-Ray's defaults (black pigment, default finish),
 * holding one reference. */
struct texture *texture_new(void);
struct texture *texture_ref(struct texture *t);
void texture_unref(struct texture *t);
/* A private copy (one reference) of t, for modification. */
struct texture *texture_copy(const struct texture *t);

#endif

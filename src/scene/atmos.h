/* atmos.h: what lies between and beyond the objects: fog, the sky sphere
 * and rainbows (the background colour is in struct scene). The parser
 * fills struct atmosphere; src/render/atmos.c applies it to rays. */
#ifndef LUCENT_ATMOS_H
#define LUCENT_ATMOS_H

#include "math/mat.h"
#include "scene/color.h"

#include <stdbool.h>
#include <stddef.h>

struct pigment;

/* fog: fog_type 1 (constant) or 2 (ground fog). */
struct fog {
	int type;
	double distance;
	struct rgbft color;
	double offset, alt;          /* ground fog */
	vec3 up;
	vec3 turbulence;             /* 0: none */
	bool has_turbulence;
	double turb_depth;
	int octaves;
	double omega, lambda;
	struct xform xf;             /* the fog's transforms (turbulence and up) */
};

/* sky_sphere: pigments layered in order (the later on top), seen in the
 * direction of a ray that escapes the scene. */
struct sky_sphere {
	struct pigment **pigments;   /* one reference each */
	size_t npigments;
	struct xform xf;
	rgb emission;                /* POV-Ray 3.7's sky_sphere emission, default 1 */
};

struct rainbow {
	vec3 direction, up;
	double angle, width, distance;
	double jitter;
	double arc_angle, falloff_angle;
	struct pigment *color_map;   /* a pigment holding the rainbow's colour_map */
};

struct atmosphere {
	struct fog *fogs;            /* in scene order */
	size_t nfogs;
	struct sky_sphere *sky;      /* NULL: none */
	struct rainbow *rainbows;
	size_t nrainbows;
};

/* Free what a (zero-initialised or filled) atmosphere owns. */
void atmos_free(struct atmosphere *a);

#endif

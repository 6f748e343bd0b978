/* atmos.h: what lies between and beyond the objects: fog, the sky sphere
 * and rainbows (the background colour is in struct scene). The parser
 * (lang/atmos_parse.c) fills struct atmosphere; src/render/atmos.c applies
 * it to rays. Defaults are POV-Ray 3.7's (fog_default, rainbow_default). */
#ifndef LUCENT_ATMOS_H
#define LUCENT_ATMOS_H

#include "math/mat.h"
#include "pattern/pattern.h"
#include "scene/color.h"

#include <stdbool.h>
#include <stddef.h>

struct pigment;
struct blend_map;

enum fog_type { FOG_CONSTANT = 1, FOG_GROUND = 2 };

/* fog: fog_type 1 (constant) or 2 (ground fog). */
struct fog {
	enum fog_type type;
	double distance;             /* <= 0: the fog is off, as in POV-Ray */
	struct rgbft color;          /* filter: how much of what is behind is tinted;
	                              * transmit: the least share of it that shows */
	double offset, alt;          /* ground fog: density 1 up to offset, then 1/(1+((h-offset)/alt)^2) */
	vec3 up;                     /* as written, turned by the transformations that follow it (the
	                              * transformations move nothing else, measured) */
	bool has_turbulence;
	struct turbulence turb;      /* amount <0,0,0>, octaves 6, omega 0.5, lambda 2 */
	double turb_depth;           /* 0.5 */
};

/* sky_sphere: pigments layered in order (the later on top), seen in the
 * direction of a ray that escapes the scene. */
struct sky_sphere {
	struct pigment **pigments;   /* one reference each, bottom first */
	size_t npigments;
	struct xform xf;             /* applied to the direction, as to a point */
	rgb emission;                /* multiplies the sky's own colour; default 1 */
};

struct rainbow {
	vec3 direction, up;          /* as written (direction must not be 0); up default y */
	double angle, width, distance;
	double jitter;               /* 0 */
	double arc_angle;            /* 360: the whole circle (POV-Ray's manual says 180, but POV-Ray
	                              * draws the whole circle unless arc_angle is given) */
	double falloff_angle;        /* no more than arc_angle: the arc fades out beyond +-falloff/2 */
	struct blend_map *color_map; /* one reference, or NULL (then the rainbow adds nothing) */
};

struct atmosphere {
	struct fog *fogs;            /* in scene order */
	size_t nfogs;
	struct sky_sphere *sky;      /* NULL: none */
	struct rainbow *rainbows;
	size_t nrainbows;
};

/* POV-Ray's defaults. */
struct fog fog_default(void);
struct rainbow rainbow_default(void);
/* A new sky sphere without pigments (emission 1, no transform). */
struct sky_sphere *sky_sphere_new(void);
/* A deep copy (pigments referenced), and freeing one. */
struct sky_sphere *sky_sphere_copy(const struct sky_sphere *s);
void sky_sphere_free(struct sky_sphere *s);
/* Add a pigment on top of the sky's layers; takes the reference. */
void sky_sphere_add(struct sky_sphere *s, struct pigment *pg);
/* Release what a rainbow owns (its colour map). */
void rainbow_clear(struct rainbow *r);

/* Add a fog or a rainbow to the atmosphere (copied; the rainbow's map
 * reference passes to the atmosphere); replace the sky sphere (taken). */
void atmos_add_fog(struct atmosphere *a, const struct fog *f);
void atmos_add_rainbow(struct atmosphere *a, const struct rainbow *r);
void atmos_set_sky(struct atmosphere *a, struct sky_sphere *s);

/* Free what a (zero-initialised or filled) atmosphere owns. */
void atmos_free(struct atmosphere *a);

#endif

/* scene.h: the scene the parser builds and the renderer reads: objects,
 * lights, camera, background and global settings. The parser fills it only
 * through these functions and the constructors in src/geom/shapes.h. */
#ifndef LUCENT_SCENE_H
#define LUCENT_SCENE_H

#include "scene/atmos.h"
#include "scene/camera.h"
#include "scene/color.h"
#include "scene/light.h"
#include "scene/object.h"

#include <stddef.h>

struct global_settings {
	double assumed_gamma;  /* the working gamma; 1.0: linear lighting */
	bool assumed_gamma_set;
	int max_trace_level;
	double adc_bailout;
	rgb ambient_light;
	rgb irid_wavelength;   /* <0.25, 0.18, 0.14>; read but, as in POV-Ray 3.7, without effect */
	int noise_generator;   /* 1, 2 (the default) or 3: for patterns that do not name one */
	int number_of_waves;   /* waves and ripples: 10 by default */
	int charset;           /* 0: ascii (the default), 1: utf8, 2: sys */
};

struct scene {
	struct object **objects; /* owned */
	size_t nobjects, cap_objects;
	struct light *lights;
	size_t nlights, cap_lights;
	struct light_group *groups; /* light_group statements; [0] unused (no group) */
	size_t ngroups, cap_groups;
	struct camera camera;
	struct rgbft background;
	struct atmosphere atmos;
	struct global_settings gs;
	double version;          /* #version in effect at the end of the parse */
	bool version_set;        /* the scene said #version at all */
};

struct scene *scene_new(void);
void scene_free(struct scene *s);
/* Takes ownership of o. */
void scene_add_object(struct scene *s, struct object *o);
void scene_add_light(struct scene *s, const struct light *l);
/* A new light group inside group `parent` (0: at the top); its number. */
int scene_add_light_group(struct scene *s, int parent);

#endif

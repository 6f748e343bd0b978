/* light.h: light sources as the parser describes them (POV-Ray's
 * light_source with its modifiers, already transformed to world space). */
#ifndef LUCENT_LIGHT_H
#define LUCENT_LIGHT_H

#include "lang/source.h"
#include "math/vec.h"
#include "scene/color.h"

#include <stdbool.h>

struct object;

enum light_kind { LIGHT_POINT, LIGHT_SPOT, LIGHT_CYLINDER, LIGHT_PARALLEL };

struct light {
	enum light_kind kind;
	vec3 pos;
	rgb color;
	bool shadowless;
	/* spotlight and cylinder: the cone or cylinder around pos -> point_at
	 * (angles in degrees for a spotlight, radii for a cylinder);
	 * parallel: light travels along pos -> point_at. */
	vec3 point_at;
	double radius, falloff, tightness;
	/* area_light: a grid of size1 x size2 lights spanning axis1, axis2. */
	bool area;
	vec3 axis1, axis2;
	int size1, size2;
	int adaptive;        /* adaptive level; 0: no adaptive subdivision */
	bool jitter, circular, orient;
	/* fade_distance/fade_power: 0 power: no fading. */
	double fade_distance, fade_power;
	bool media_interaction, media_attenuation; /* read; no media in lucent yet */
	struct object *looks_like;        /* owned; NULL: none */
	struct object *projected_through; /* owned; NULL: none */
	/* light_group: the group the light belongs to (0: the scene's global
	 * lights, which light every object outside groups and the groups that
	 * say global_lights). */
	int group;
	struct srcpos srcpos;
};

#endif

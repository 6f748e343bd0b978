/* light.h: light sources as the parser describes them (POV-Ray's
 * light_source with its modifiers, already transformed to world space),
 * and light groups. */
#ifndef LUCENT_LIGHT_H
#define LUCENT_LIGHT_H

#include "lang/source.h"
#include "math/mat.h"
#include "scene/color.h"

#include <stdbool.h>

struct object;

/* The kind of cone: a point light has none; a spotlight's is an angle
 * around pos -> point_at, a cylinder light's a radius around that axis. */
enum light_kind { LIGHT_POINT, LIGHT_SPOT, LIGHT_CYLINDER };

struct light {
	enum light_kind kind;
	vec3 pos;
	rgb color;
	bool shadowless;     /* casts no shadows and makes no highlights */
	/* spotlight: degrees (default 30, 45, 0); cylinder: radii (default
	 * 0.75, 1, 0). Light travels from pos toward point_at. */
	vec3 point_at;
	double radius, falloff, tightness;
	/* parallel: the light's rays all run along pos -> point_at; shadows
	 * are cast only between the point and the plane through pos across
	 * that direction. */
	bool parallel;
	/* area_light: a grid of size1 x size2 lights spanning axis1, axis2
	 * around pos (shadows only; the shading uses pos, unless
	 * area_illumination). */
	bool area;
	vec3 axis1, axis2;
	int size1, size2;
	int adaptive;        /* adaptive level; -1: every sample is tested */
	bool jitter, circular, orient;
	bool area_illumination; /* diffuse and highlights averaged over the grid's points */
	/* fade_distance/fade_power: light is scaled by
	 * 2 / (1 + (d / fade_distance)^fade_power) when both are > 0. */
	double fade_distance, fade_power;
	bool media_interaction, media_attenuation; /* read; lucent has no media */
	struct object *looks_like;        /* owned; NULL: none (see light_parse.c) */
	struct object *projected_through; /* owned; NULL: none */
	/* light_group: the group the light belongs to (0: the scene's global
	 * lights, which light every object outside groups and the groups that
	 * say global_lights). */
	int group;
	struct srcpos srcpos;
};

/* A light_group: lights of group g light the objects of g and of the
 * groups nested in it (whose parent chain reaches g). */
struct light_group {
	int parent;          /* the enclosing group; 0: none */
	bool global_lights;  /* the scene's global lights light it too */
	/* Not a light group but the lights read in one CSG's body (its
	 * carried_lights): they light the scene as global lights when that CSG
	 * is in the scene, and nothing when it is only declared. */
	bool carrier;
};

/* POV-Ray's defaults: a white point light at the origin. */
struct light light_default(void);
/* A deep copy of l's owned objects into c (c is a byte copy of l). */
void light_copy_parts(struct light *c);
/* Free what l owns (not l itself). */
void light_free_parts(struct light *l);
/* Move every point and vector of l by t (looks_like and projected_through
 * objects too). */
void light_transform(struct light *l, const struct xform *t);

#endif

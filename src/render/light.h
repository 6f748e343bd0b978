/* light.h: the lights as the tracer samples them: direction, distance and
 * strength at a point (spotlight and cylinder cones, fading, parallel
 * lights), the lights each light_group's objects see, and POV-Ray's area
 * lights (a size1 x size2 grid, its adaptive subdivision, jitter, circular
 * and orient). Everything a light needs is worked out once, in
 * light_set_new; nothing here allocates per ray. */
#ifndef LUCENT_RENDER_LIGHT_H
#define LUCENT_RENDER_LIGHT_H

#include "render/prepare.h"

#include <stdint.h>

/* One light, ready for sampling. */
struct light_rt {
	const struct light *l;
	vec3 pos;
	rgb color;
	bool along_axis;      /* parallel or cylinder: the light runs along `axis` */
	vec3 axis;            /* unit, pos -> point_at */
	bool spot, cylinder;  /* a cone to apply (only with FEAT_SPOTLIGHTS) */
	double cos_radius, cos_falloff; /* spotlight */
	double radius, falloff;         /* cylinder */
	double tightness;
	bool fade;            /* fade_distance and fade_power (with FEAT_LIGHT_FADE) */
	double fade_distance, fade_power;
	bool shadows;         /* casts shadows (not shadowless, and FEAT_SHADOWS) */
	bool highlights;      /* makes highlights (not shadowless) */
	bool area;            /* sampled as an area (FEAT_AREA_LIGHTS, more than one sample) */
	int n1, n2, adaptive; /* grid size; adaptive level, -1: every sample */
	bool jitter, circular, orient;
	vec3 axis1, axis2;    /* full edge vectors */
	double len1, len2;    /* their lengths, for orient */
	const struct object *projector; /* projected_through, or NULL */
	size_t slot;          /* its first last-blocker slot (one per grid column of an area light) */
	/* area_illumination (an area light, with or without shadows): the
	 * diffuse and highlights are the mean over the n1 x n2 points of the
	 * grid, each lighting from its own direction with its own cone and
	 * fading; illum_off is the light's first entry in the tracer's table
	 * of light_point. */
	bool illum;
	size_t illum_off;
};

/* The lights of a scene, and for each light group the lights that reach
 * its objects. */
struct light_set {
	struct light_rt *v;
	size_t n;
	size_t **group;       /* per group (0: objects outside groups): light indices */
	size_t *ngroup;
	size_t ngroups;
	size_t slots;         /* last-blocker slots in all */
	size_t max_samples;   /* the largest area grid */
	size_t illum_points;  /* the grid points of all area_illumination lights */
};

/* The lights of p's scene as the tracer uses them (p->features decides
 * which effects are computed). Free with light_set_free. */
struct light_set *light_set_new(const struct prepared *p);
void light_set_free(struct light_set *s);

/* One point of an area_illumination grid seen from a point. */
struct light_point {
	vec3 dir;       /* unit, toward it */
	double atten;   /* its cone and fading; 0: no light from it */
};

/* A light seen from a point. */
struct light_ray {
	vec3 dir;       /* unit, toward the light (for shading) */
	double dist;    /* how far shadows are tested; 0: not at all (a parallel light's plane is behind) */
	double atten;   /* cone and fading, > 0 */
};

/* The light L at point pt; false when none arrives there (outside a cone,
 * behind a cylinder light: atten is then 0, dir and dist are set; at the
 * light itself: dir is 0 too). */
bool light_at(const struct light_rt *L, vec3 pt, struct light_ray *out);

/* Per-thread scratch for area lights: each sample's result once per point. */
struct area_scratch {
	rgb *val;
	uint32_t *stamp;
	uint32_t now;
	size_t n;
};
void area_scratch_init(struct area_scratch *a, size_t max_samples);
void area_scratch_free(struct area_scratch *a);

/* The shadow test of one sample: the light arriving at the point from
 * `target` (a point on the light, or, for light along an axis, the point
 * where the way toward the sample leaves the sample's plane). `column` picks the
 * last-blocker slot. */
typedef rgb (*area_test_fn)(void *ctx, vec3 target, int column);

/* The light of area light L arriving at pt, as POV-Ray computes it: corners of the grid first, blocks subdivided where
 * their corners differ by more than 0.1 (sum over the channels) or while
 * the level is below `adaptive`, each block the mean of its halves. Jitter
 * comes from a hash of pt and the sample, so the result does not depend
 * on threads or order. */
rgb light_area(const struct light_rt *L, vec3 pt, struct area_scratch *sc,
               area_test_fn test, void *ctx);

/* The n1 x n2 points of area light L seen from pt, placed where
 * light_area's samples lie (orient, circular and jitter applied), each
 * with the direction and attenuation area_illumination lights pt with
 * from it (see light.c): point (i, j) goes to out[j * n1 + i]. False when
 * no light arrives from any of them. */
bool light_area_points(const struct light_rt *L, vec3 pt, struct light_point *out);

#endif

/* prepare.h: turn a parsed scene into what the tracer reads: world bounds,
 * the BVH, the list of unbounded objects, the resolved camera and the
 * feature mask (which effects the scene can produce at all). Everything
 * here is decided once, so the per-ray path tests nothing it could know in
 * advance. */
#ifndef LUCENT_PREPARE_H
#define LUCENT_PREPARE_H

#include "accel/bvh.h"
#include "scene/scene.h"

#include <stdint.h>

struct lens;

enum feature {
	FEAT_SHADOWS = 1 << 0,    /* some light casts shadows onto something */
	FEAT_PHONG = 1 << 1,      /* some finish has a phong highlight */
	FEAT_SPECULAR = 1 << 2,   /* some finish has a specular highlight */
	FEAT_REFLECTION = 1 << 3, /* some finish reflects */
	FEAT_TRANSPARENCY = 1 << 4, /* some pigment filters or transmits: transmitted rays, transparent shadows */
	FEAT_REFRACTION = 1 << 5, /* a see-through object has an ior other than 1 */
	FEAT_NORMALS = 1 << 6,    /* some texture perturbs its normal */
	FEAT_IRID = 1 << 7,       /* some finish is iridescent */
	FEAT_FADE = 1 << 8,       /* a see-through object's interior fades light */
	FEAT_DISPERSION = 1 << 9, /* a refracting interior disperses light */
	FEAT_CAUSTICS = 1 << 10,  /* a see-through object's interior has fake caustics */
	FEAT_FRESNEL = 1 << 11,   /* some reflection block uses fresnel */
	FEAT_LAYERS = 1 << 12,    /* layered, patterned or material-mapped textures */
	FEAT_UV = 1 << 13,        /* some pattern is uv-mapped */
	FEAT_AREA_LIGHTS = 1 << 14, /* some shadow-casting light is an area light, or any has area_illumination */
	FEAT_SPOTLIGHTS = 1 << 15,  /* some light is a spotlight or cylinder (cones) */
	FEAT_LIGHT_FADE = 1 << 16,  /* some light fades with distance */
	FEAT_FOCAL_BLUR = 1 << 17,  /* the camera has an aperture */
	FEAT_FOG = 1 << 18,         /* fog */
	FEAT_SKY = 1 << 19,         /* sky_sphere */
	FEAT_RAINBOW = 1 << 20,     /* rainbow */
	FEAT_ANTIALIAS = 1 << 21,   /* +A: more than one sample per pixel where needed */
	FEAT_INTERIORS = 1 << 22,   /* fog or a rainbow seen through see-through objects: rays track the
	                             * interiors they are in, for no fog inside solid objects */
	FEAT__COUNT = 23
};

/* Rays track the media they are in (refraction, fading, Fresnel, fog
 * inside objects) only when the scene has one of these. */
#define FEAT_MEDIA (FEAT_REFRACTION | FEAT_FADE | FEAT_FRESNEL | FEAT_DISPERSION | FEAT_INTERIORS)

/* The interiors a ray is inside, innermost last, and the band of the
 * spectrum it carries. Passed by pointer and copied on change: a ray
 * entering a surface gets a new one. Deeper nesting
 * than MEDIUM_MAX keeps the outer interiors and forgets the rest. */
enum { MEDIUM_MAX = 16 };
struct medium {
	int n;
	const struct interior *in[MEDIUM_MAX];
	uint32_t solid; /* bit i: in[i] is that of an object that is not hollow (no fog or rainbow there) */
	bool dispersed; /* the ray is one band of a dispersed ray: it disperses no more */
	double hue;     /* its band's centre, -1/2 (red) to 1/2 (violet); 0 if not dispersed */
};

struct prepared {
	const struct scene *scene;
	struct bvh *bvh;                 /* the bounded objects */
	const struct object **unbounded; /* planes and other infinite objects */
	size_t nunbounded;
	unsigned features;               /* enum feature */
	int max_depth;                   /* max_trace_level */
	bool signature;                  /* --signature: flat colour per primitive */
	int quality;                     /* +Q, 0 to 11 (9 by default): see prepare_quality */
	struct medium camera_medium;     /* the interiors around the camera (with FEAT_MEDIA, fog or rainbows) */
	struct lens *lens;               /* focal blur (render/camsample.h); NULL without it */
};

/* Prepare s for rendering. s must outlive the result. */
struct prepared *prepare_scene(struct scene *s);
void prepared_free(struct prepared *p);
/* Leave out what POV-Ray's quality level q (+Q) leaves out: below 8
 * reflection and normal perturbation, below 6 transmitted rays (shadows
 * still filter through transparent objects; and
 * patterned pigments with a quick_color show that colour), below 5 area
 * lights, below 4 shadows, below 2 all lighting (each surface shows its
 * pigment's colour). Masks p->features. */
void prepare_quality(struct prepared *p, int q);
/* The feature mask of a scene, as prepare_scene computes it. */
unsigned prepare_features(const struct scene *s);
const char *feature_name(enum feature f);

#endif

/* prepare.h: turn a parsed scene into what the tracer reads: world bounds,
 * the BVH, the list of unbounded objects, the resolved camera and the
 * feature mask (which effects the scene can produce at all). Everything
 * here is decided once, so the per-ray path tests nothing it could know in
 * advance. */
#ifndef LUCENT_PREPARE_H
#define LUCENT_PREPARE_H

#include "accel/bvh.h"
#include "scene/scene.h"

enum feature {
	FEAT_SHADOWS = 1 << 0,    /* some light casts shadows onto something */
	FEAT_PHONG = 1 << 1,      /* some finish has a phong highlight */
	FEAT_SPECULAR = 1 << 2,   /* some finish has a specular highlight */
	FEAT_REFLECTION = 1 << 3, /* some finish reflects */
	FEAT__COUNT = 4
};

struct prepared {
	const struct scene *scene;
	struct bvh *bvh;                 /* the bounded objects */
	const struct object **unbounded; /* planes and other infinite objects */
	size_t nunbounded;
	unsigned features;               /* enum feature */
	int max_depth;                   /* max_trace_level */
	bool signature;                  /* --signature: flat colour per primitive */
};

/* Prepare s for rendering. s must outlive the result. */
struct prepared *prepare_scene(struct scene *s);
void prepared_free(struct prepared *p);
/* The feature mask of a scene, as prepare_scene computes it. */
unsigned prepare_features(const struct scene *s);
const char *feature_name(enum feature f);

#endif

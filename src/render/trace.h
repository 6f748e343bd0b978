/* trace.h: casting rays through a prepared scene and shading what they hit
 * (Whitted: direct light through transparent shadows, POV-Ray's finish
 * terms, reflection, refraction through nested interiors, layered and
 * patterned textures; the formulas are in shade.c). One tracer per thread: it holds that thread's statistics and
 * scratch, so the per-ray path allocates nothing and shares no writes. */
#ifndef LUCENT_TRACE_H
#define LUCENT_TRACE_H

#include "render/light.h"
#include "render/prepare.h"
#include "render/stats.h"

#include <signal.h>

struct lit;

struct tracer {
	const struct prepared *p;
	struct stats stats;
	const struct object **last_blocker; /* per light (per grid column of an area light): the
	                                     * object that last shadowed it */
	struct lit *lit;                     /* per light: scratch for one surface's lighting */
	struct light_set *lights;            /* the lights as sampled, and who sees which */
	struct area_scratch area;            /* area-light samples of the point being lit */
	struct light_point *illum;           /* area_illumination: each grid point as seen from the
	                                      * point being lit (at the light's illum_off) */
	/* The share of the background seen through what the last
	 * trace_ray_in call saw (POV-Ray's transmit channel: 1 where the
	 * background shows, 0 on an opaque object), and its sum over the
	 * trace_ray calls since the caller last cleared it, for the alpha
	 * channel: a pixel's alpha is 1 - camera_transmit / camera_rays. */
	double transmit;
	double camera_transmit;
	int camera_rays;
	double camera_limit;                 /* how far camera rays see (camera_ray_limit) */
	volatile sig_atomic_t *stop;         /* the render's stop flag (render_opts), or NULL: a
	                                      * pixel of many samples looks at it too */
};

void tracer_init(struct tracer *tr, const struct prepared *p);
void tracer_free(struct tracer *tr);

/* Closest hit along r with tmin < t < tmax among objects without a `skip`
 * flag (OBJ_NO_IMAGE for camera rays, OBJ_NO_REFLECTION for reflected). */
bool trace_closest(const struct prepared *p, const struct ray *r, double tmin, double tmax, unsigned skip, struct hit *h);

/* The colour seen along r (direction need not be unit). `depth` counts the
 * bounces so far (camera rays: 1). *hit_anything tells if an object (not
 * the background) was seen. Adds the ray's transmit to tr->camera_transmit
 * and counts it in tr->camera_rays. */
rgb trace_ray(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, bool *hit_anything);
/* The same for a secondary ray: `weight` is how much its colour can still
 * change the pixel (rays below adc_bailout are not traced by the caller),
 * `med` the interiors it travels in (NULL: none). Sets tr->transmit. */
rgb trace_ray_in(struct tracer *tr, const struct ray *r, int depth, enum ray_kind kind, double weight,
                 const struct medium *med, bool *hit_anything);

/* The offset that keeps a secondary ray from finding its own surface: a
 * relative tolerance on the magnitude of the coordinates involved, so the
 * same scene behaves the same at 1e-4 scale and 1e5 units from the origin. */
double trace_epsilon(vec3 p, vec3 from);

#endif

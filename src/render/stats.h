/* stats.h: render statistics. Each thread counts into its own struct; the
 * counts are summed at the end, so counting costs no synchronisation. */
#ifndef LUCENT_STATS_H
#define LUCENT_STATS_H

#include <stdint.h>
#include <stdio.h>

enum ray_kind { RAY_CAMERA, RAY_SHADOW, RAY_REFLECTED, RAY_REFRACTED, RAY__COUNT };

struct stats {
	uint64_t rays[RAY__COUNT];
	uint64_t pixels;
	uint64_t samples;           /* camera samples (antialiasing takes several per pixel) */
	uint64_t aa_pixels;         /* pixels antialiasing supersampled */
	uint64_t shadow_cache_hits; /* shadow rays answered by the last blocker */
};

void stats_add(struct stats *into, const struct stats *from);
const char *stats_ray_name(enum ray_kind k);

#endif

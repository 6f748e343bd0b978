/* stats.c: render statistics (see stats.h). */
#include "render/stats.h"

void stats_add(struct stats *into, const struct stats *from)
{
	for (int k = 0; k < RAY__COUNT; k++)
		into->rays[k] += from->rays[k];
	into->pixels += from->pixels;
	into->samples += from->samples;
	into->aa_pixels += from->aa_pixels;
	into->shadow_cache_hits += from->shadow_cache_hits;
}

const char *stats_ray_name(enum ray_kind k)
{
	static const char *const names[RAY__COUNT] = {"camera", "shadow", "reflected", "refracted"};
	return k < RAY__COUNT ? names[k] : "?";
}

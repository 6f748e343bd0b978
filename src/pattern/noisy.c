/* noisy.c: the noise-based patterns (see kinds.h). IN PROGRESS: being written. */
#include "pattern/kinds.h"

PATTERN_FN(agate)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(bozo)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(bumps)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(cells)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(crackle)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(dents)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(facets)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(granite)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(marble)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(ripples)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(spotted)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(waves)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(wood)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(wrinkles)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

bool pattern_special_normal(const struct pattern *pt, double amount, vec3 p, vec3 n,
                            const struct pattern_ctx *ctx, vec3 *out)
{
	(void)pt; (void)amount; (void)p; (void)n; (void)ctx; (void)out;
	return false;
}

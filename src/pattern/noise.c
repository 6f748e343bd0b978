/* noise.c: POV-Ray's noise and turbulence (see pattern.h). IN PROGRESS. */
#include "pattern/pattern.h"

double noise3(vec3 p, int generator)
{
	(void)p; (void)generator;
	return 0.5;
}

vec3 dnoise3(vec3 p, int generator)
{
	(void)p; (void)generator;
	return v3(0, 0, 0);
}

double turbulence1(vec3 p, const struct turbulence *t, int generator)
{
	(void)p; (void)t; (void)generator;
	return 0;
}

vec3 turbulence3(vec3 p, const struct turbulence *t, int generator)
{
	(void)p; (void)t; (void)generator;
	return v3(0, 0, 0);
}

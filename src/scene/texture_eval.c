/* texture_eval.c: evaluating pigments and normals at a point (see
 * texture.h). IN PROGRESS: being written. */
#include "scene/texture.h"

struct rgbft pigment_eval(const struct pigment *pg, const struct pattern_ctx *ctx)
{
	(void)ctx;
	return pg->color;
}

vec3 normal_eval(const struct normal *nm, vec3 n, const struct pattern_ctx *ctx)
{
	(void)nm; (void)ctx;
	return n;
}

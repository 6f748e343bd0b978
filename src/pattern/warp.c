/* warp.c: carrying a point into pattern space through the pattern's
 * transformations and warps (see pattern.h). IN PROGRESS: being written. */
#include "pattern/pattern.h"

vec3 pattern_point(const struct pattern *pt, vec3 p)
{
	for (int i = pt->nops - 1; i >= 0; i--) {
		const struct pattern_op *op = &pt->ops[i];
		if (op->kind == POP_TRANSFORM)
			p = mat_point(&op->xf.inv, p);
	}
	return p;
}

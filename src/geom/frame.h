/* frame.h: the frame POV-Ray builds its boxes of round primitives in
 * (cylinder, cone, disc), shared so they agree to the last bit. */
#ifndef LUCENT_GEOM_FRAME_H
#define LUCENT_GEOM_FRAME_H

#include "math/mat.h"

/* The map POV-Ray builds the boxes of these shapes with (found by
 * measuring min_extent and max_extent; see cylinder.c and disc.c): the
 * rotation taking +z to the unit vector w about z x w, with columns
 * x' = (1 - wx^2/(1-wz), -wx wy/(1-wz), wx),
 * y' = (-wx wy/(1-wz), 1 - wy^2/(1-wz), wy) and z' = w (for w = +z the
 * identity; for w = -z the formula gives the mirror in z, which no
 * symmetric box can tell from a rotation). The columns are scaled by sx,
 * sy and sz, and org is the fourth column. */
static inline mat4 geom_axis_frame(vec3 w, double sx, double sy, double sz, vec3 org)
{
	vec3 xa = v3(1, 0, 0), ya = v3(0, 1, 0);
	double q = 1 - w.z;
	if (q > 0) {
		xa = v3(1 - w.x * w.x / q, -w.x * w.y / q, w.x);
		ya = v3(-w.x * w.y / q, 1 - w.y * w.y / q, w.y);
	}
	mat4 f = mat_identity();
	vec3 col[4] = {v3_scale(xa, sx), v3_scale(ya, sy), v3_scale(w, sz), org};
	for (int j = 0; j < 4; j++) {
		f.m[0][j] = col[j].x;
		f.m[1][j] = col[j].y;
		f.m[2][j] = col[j].z;
	}
	return f;
}

#endif

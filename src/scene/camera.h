/* camera.h: the camera as the parser describes it (POV-Ray's vectors) and
 * as the renderer uses it (a resolved frame). */
#ifndef LUCENT_CAMERA_H
#define LUCENT_CAMERA_H

#include "lang/source.h"
#include "math/mat.h"

#include <stdbool.h>

enum camera_kind { CAMERA_PERSPECTIVE };

struct camera {
	enum camera_kind kind;
	vec3 location, direction, right, up, sky;
	struct srcpos pos;
};

/* POV-Ray's default camera: at the origin looking along +z, right
 * <1.33,0,0>, up y, direction z. */
struct camera camera_default(void);
/* Point the camera at `at`, keeping the lengths of direction, right and up
 * and the handedness of the frame, with `sky` as the up reference. Returns
 * false if `at` is the location or straight along the sky vector. */
bool camera_look_at(struct camera *c, vec3 at);
/* Set the horizontal field of view (degrees) by rescaling direction. */
void camera_set_angle(struct camera *c, double degrees);
void camera_transform(struct camera *c, const struct xform *t);

#endif

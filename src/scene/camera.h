/* camera.h: the camera as the parser describes it (POV-Ray's vectors) and
 * as the renderer uses it (camera_ray). */
#ifndef LUCENT_CAMERA_H
#define LUCENT_CAMERA_H

#include "lang/source.h"
#include "math/mat.h"

#include <stdbool.h>

enum camera_kind {
	CAMERA_PERSPECTIVE, CAMERA_ORTHOGRAPHIC, CAMERA_FISHEYE, CAMERA_ULTRA_WIDE_ANGLE,
	CAMERA_OMNIMAX, CAMERA_PANORAMIC, CAMERA_CYLINDER, CAMERA_SPHERICAL
};

struct camera {
	enum camera_kind kind;
	int cylinder_type;     /* CAMERA_CYLINDER: 1 to 4 */
	vec3 location, direction, right, up, sky;
	double angle;          /* horizontal angle in degrees; 0: not given */
	double v_angle;        /* spherical: vertical angle; 0: not given */
	/* Focal blur: aperture 0 is a pinhole (no blur). */
	double aperture;
	vec3 focal_point;
	int blur_samples_min, blur_samples_max;
	double confidence, variance;
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

/* The ray through image position (x, y) (pixels from the top-left corner
 * of a w x h image; a pixel's centre is at +0.5) with the lens sample
 * (lu, lv) in [-0.5, 0.5]^2 (0, 0: the centre; used with focal blur).
 * The direction is unit. Returns false where the camera has no ray (e.g.
 * outside a fisheye's circle): the pixel is then black, as in POV-Ray. */
bool camera_ray(const struct camera *c, double x, double y, int w, int h, double lu, double lv,
                struct ray *r);

#endif

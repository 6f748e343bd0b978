/* camera.h: the camera as the parser describes it (POV-Ray's vectors) and
 * as the renderer uses it (camera_ray). Every projection maps an image
 * position to a ray exactly as POV-Ray 3.7 does; the formulas, measured
 * from POV-Ray's renders, are written out in camera.c and in the Cameras
 * section of doc/lights-cameras.md. */
#ifndef LUCENT_CAMERA_H
#define LUCENT_CAMERA_H

#include "lang/source.h"
#include "math/mat.h"

#include <stdbool.h>

struct pigment;
struct normal;

/* One face of a mesh camera, in world space. */
struct camera_face {
	vec3 p[3];            /* corners */
	vec3 centroid;
	vec3 n;               /* unit flat normal (c - a) x (b - a): the ray's direction */
	vec3 vn[3];           /* unit vertex normals (smooth), when has_normals */
	double uv[3][2];      /* when has_uv */
	bool has_normals, has_uv;
};

/* mesh_camera { RAYS DISTRIBUTION [MAX_DISTANCE] mesh { ... } ... [smooth] }:
 * shared by the camera's copies (reference-counted). */
struct mesh_cam {
	int refs;
	int rays;             /* rays per pixel, >= 1 */
	int dist;             /* distribution type 0 to 3 */
	double max_dist;      /* ray length limit; 0: none */
	bool smooth;          /* distribution 3: interpolate vertex normals */
	int nmesh;
	size_t *first;        /* [k]: first face of mesh k; [nmesh]: the total */
	struct camera_face *face;
};

enum camera_kind {
	CAMERA_PERSPECTIVE, CAMERA_ORTHOGRAPHIC, CAMERA_FISHEYE, CAMERA_ULTRA_WIDE_ANGLE,
	CAMERA_OMNIMAX, CAMERA_PANORAMIC, CAMERA_CYLINDER, CAMERA_SPHERICAL, CAMERA_MESH
};

struct camera {
	enum camera_kind kind;
	int cylinder_type;     /* CAMERA_CYLINDER: 1 to 4 */
	vec3 location, direction, right, up, sky;
	double angle;          /* horizontal angle in degrees; negative: not given
	                        * (the kind's default: 90, spherical 360) */
	double v_angle;        /* spherical: vertical angle; negative: half the horizontal */
	/* Focal blur: on when aperture > 0 and blur_samples_max > 0. */
	double aperture;       /* lens size: POV-Ray's lens radius is aperture/4 */
	vec3 focal_point;      /* a point of the plane in focus (parallel to right and up) */
	int blur_samples_min, blur_samples_max;
	double confidence, variance;
	struct pigment *bokeh; /* focal blur's lens shape (a reference), or NULL: round */
	struct mesh_cam *mesh; /* CAMERA_MESH: its faces (a reference) */
	struct normal *normal; /* camera ray perturbation (a reference), or NULL */
	struct srcpos pos;

	/* Derived by camera_update from the fields above; read by camera_ray. */
	vec3 dn, rn, un;       /* unit direction, right and up */
	double rl, ul;         /* lengths of right and up */
	double h_rad, v_rad;   /* the angles in effect, in radians */
	double focal_dist;     /* distance of the plane in focus along dn */
	double omni_sx, omni_sy, omni_oy; /* omnimax: image to lens-plane scale and offset */
};

/* POV-Ray's default camera: perspective, at the origin looking along +z,
 * right <1.33,0,0>, up y, direction z, sky y; no focal blur (confidence
 * 0.9, variance 1/128). Already updated. */
struct camera camera_default(void);
/* The camera holds references (the bokeh pigment ...): a struct copy
 * needs camera_copy, and every camera is cleared with camera_clear. */
void camera_copy(struct camera *dst, const struct camera *src);
/* Drop the camera's references; it stays a valid camera without them. */
void camera_clear(struct camera *c);
/* Point the camera at `at`, keeping the lengths of direction, right and up
 * and the handedness of the frame, with `sky` as the up reference. When
 * `at` lies straight along the sky vector (or sky is zero), the given
 * right vector is kept as the reference instead, and *along_sky is set (a
 * warning for the parser), as POV-Ray does. Returns false if `at` is the
 * location, or if right is also along the new direction. */
bool camera_look_at(struct camera *c, vec3 at, bool *along_sky);
/* Set the horizontal field of view of a perspective camera (degrees,
 * 0 < degrees < 180) by rescaling direction:
 * |direction| = 0.5 |right| / tan(degrees / 2). */
void camera_set_angle(struct camera *c, double degrees);
/* Move the camera's location, frame and focal point by t. */
void camera_transform(struct camera *c, const struct xform *t);
/* Recompute the derived fields; call after changing any other field. */
void camera_update(struct camera *c);

/* The ray through image position (x, y) (pixels from the top-left corner
 * of a w x h image; a pixel's centre is at +0.5) with the lens sample
 * (lu, lv) in the disc of radius 0.5 (0, 0: the centre, a pinhole; used
 * with focal blur). The direction is unit. Returns false where the camera
 * has no ray (outside a fisheye's or omnimax's circle): the pixel is then
 * black, as in POV-Ray. */
bool camera_ray(const struct camera *c, double x, double y, int w, int h, double lu, double lv,
                struct ray *r);

/* Mesh camera: the ray number `k` (0 <= k < rays) of the pixel at image
 * position (x, y) (see camera_ray). Returns false when no face belongs to
 * it: that ray is not shot and does not count in the pixel's average. */
bool camera_mesh_ray(const struct camera *c, double x, double y, int w, int h, int k, struct ray *r);
/* How far camera rays see: a mesh camera's max_distance, INFINITY for
 * every other camera. A camera ray that meets nothing closer (measured
 * from its origin, its direction being unit) sees the background; rays
 * after the first hit are not limited (measured in POV-Ray: a mirror at
 * distance 3 shows a plane 6 further with max_distance 3.5). */
double camera_ray_limit(const struct camera *c);
/* Drop a reference to m (NULL is fine). */
void mesh_cam_unref(struct mesh_cam *m);

#endif

/* camera.c: camera description (see camera.h). */
#include "scene/camera.h"

struct camera camera_default(void)
{
	struct camera c = {
		.kind = CAMERA_PERSPECTIVE,
		.location = {0, 0, 0},
		.direction = {0, 0, 1},
		.right = {1.33, 0, 0},
		.up = {0, 1, 0},
		.sky = {0, 1, 0},
	};
	return c;
}

bool camera_look_at(struct camera *c, vec3 at)
{
	double dl = v3_len(c->direction), rl = v3_len(c->right), ul = v3_len(c->up);
	/* A left-handed frame has right = up x direction pointing along right;
	 * a scene that flips right (right -x*4/3) keeps the flip. */
	double hand = v3_dot(v3_cross(c->up, c->direction), c->right);
	vec3 d = v3_sub(at, c->location);
	if (v3_len(d) == 0)
		return false;
	d = v3_norm(d);
	vec3 r = v3_cross(c->sky, d);
	if (v3_len(r) == 0)
		return false;
	r = v3_norm(r);
	vec3 u = v3_norm(v3_cross(d, r));
	if (hand < 0)
		r = v3_neg(r);
	c->direction = v3_scale(d, dl);
	c->right = v3_scale(r, rl);
	c->up = v3_scale(u, ul);
	return true;
}

void camera_set_angle(struct camera *c, double degrees)
{
	double rl = v3_len(c->right);
	double half = degrees * (M_PI / 360.0);
	double dl = 0.5 * rl / tan(half);
	c->direction = v3_scale(v3_norm(c->direction), dl);
}

void camera_transform(struct camera *c, const struct xform *t)
{
	c->location = mat_point(&t->fwd, c->location);
	c->direction = mat_dir(&t->fwd, c->direction);
	c->right = mat_dir(&t->fwd, c->right);
	c->up = mat_dir(&t->fwd, c->up);
}

bool camera_ray(const struct camera *c, double x, double y, int w, int h, double lu, double lv,
                struct ray *r)
{
	(void)lu;
	(void)lv;
	double sx = x / w - 0.5;
	double sy = 0.5 - y / h;
	vec3 d = v3_add(c->direction, v3_add(v3_scale(c->right, sx), v3_scale(c->up, sy)));
	r->org = c->location;
	r->dir = v3_norm(d);
	return true;
}

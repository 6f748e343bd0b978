/* camsample.c: camera samples (see camsample.h). */
#include "render/camsample.h"

rgb camera_sample(struct tracer *tr, double x, double y, int w, int h, int px, int py, uint32_t sample,
                  bool *any)
{
	(void)px;
	(void)py;
	(void)sample;
	const struct camera *cam = &tr->p->scene->camera;
	struct ray r;
	*any = false;
	if (!camera_ray(cam, x, y, w, h, 0, 0, &r))
		return rgb_make(0, 0, 0);
	return trace_ray(tr, &r, 1, RAY_CAMERA, any);
}

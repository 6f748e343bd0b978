/* camsample.c: camera samples (see camsample.h): one pinhole ray, or with
 * focal blur the lens samples of POV-Ray's adaptive scheme.
 *
 * Focal blur traces between blur_samples_min and blur_samples_max rays
 * per call. Each takes a point of the lens (a disc) and a point of the
 * pixel around (x, y), from a Halton sequence (bases 2 and 3 for the lens,
 * 5 and 7 for the pixel) shifted by an offset hashed from (px, py, sample,
 * purpose), so every pixel sees its own well-spread pattern and the image
 * does not depend on the thread count. After the minimum, sampling stops
 * once the mean colour is known closely enough: with n samples of
 * per-channel variance s^2, when z^2 s^2 / n < variance in every channel,
 * z being the two-sided normal quantile of `confidence` (1.645 for the
 * default 0.9). The smaller `variance`, the more samples; variance 0 takes
 * the maximum always, as in POV-Ray. */
#include "render/camsample.h"

#include "math/hash.h"

/* Purposes for hash_uniform: 'LENS' in the high bytes, the dimension in
 * the low one. */
enum { PURPOSE_LENS = 0x4c454e00u };

/* The radical inverse of i in base b (the Halton sequence). */
static double radical_inverse(uint32_t i, uint32_t b)
{
	double inv = 1.0 / b, f = inv, r = 0;
	while (i > 0) {
		r += f * (double)(i % b);
		i /= b;
		f *= inv;
	}
	return r;
}

/* Component k of the shifted Halton point i (in [0, 1)). */
static double lens_dim(uint32_t i, uint32_t base, double shift)
{
	double v = radical_inverse(i, base) + shift;
	return v >= 1 ? v - 1 : v;
}

rgb camera_sample(struct tracer *tr, double x, double y, int w, int h, int px, int py, uint32_t sample,
                  bool *any)
{
	const struct camera *cam = &tr->p->scene->camera;
	struct ray r;
	*any = false;
	if (!(tr->p->features & FEAT_FOCAL_BLUR)) {
		if (!camera_ray(cam, x, y, w, h, 0, 0, &r))
			return rgb_make(0, 0, 0);
		return trace_ray(tr, &r, 1, RAY_CAMERA, any);
	}

	double shift[4];
	static const uint32_t bases[4] = {2, 3, 5, 7};
	for (int k = 0; k < 4; k++)
		shift[k] = hash_uniform((uint32_t)px, (uint32_t)py, sample, PURPOSE_LENS + (uint32_t)k);
	/* Welford's running mean and sum of squared deviations per channel. */
	double mean[3] = {0, 0, 0}, m2[3] = {0, 0, 0};
	int n = 0;
	for (int i = 0; i < cam->blur_samples_max; i++) {
		uint32_t s = (uint32_t)i + 1; /* Halton point 0 is the corner */
		double a = lens_dim(s, bases[0], shift[0]), b = lens_dim(s, bases[1], shift[1]);
		double rad = 0.5 * sqrt(a), phi = 2 * M_PI * b;
		double jx = lens_dim(s, bases[2], shift[2]) - 0.5, jy = lens_dim(s, bases[3], shift[3]) - 0.5;
		rgb c = rgb_make(0, 0, 0);
		bool hit = false;
		if (camera_ray(cam, x + jx, y + jy, w, h, rad * cos(phi), rad * sin(phi), &r))
			c = trace_ray(tr, &r, 1, RAY_CAMERA, &hit);
		*any = *any || hit;
		double v[3] = {c.r, c.g, c.b};
		n++;
		for (int k = 0; k < 3; k++) {
			double d = v[k] - mean[k];
			mean[k] += d / n;
			m2[k] += d * (v[k] - mean[k]);
		}
		if (n >= cam->blur_samples_min && n >= 2) {
			bool settled = true;
			for (int k = 0; k < 3 && settled; k++) {
				double var = m2[k] / (n - 1);
				settled = cam->blur_z2 * var / n < cam->variance;
			}
			if (settled)
				break;
		}
	}
	return rgb_make(mean[0], mean[1], mean[2]);
}

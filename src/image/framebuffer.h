/* framebuffer.h: the float RGBA image the renderer fills, in the working
 * colour space (linear when assumed_gamma is 1). */
#ifndef LUCENT_FRAMEBUFFER_H
#define LUCENT_FRAMEBUFFER_H

#include <stddef.h>

struct framebuffer {
	int width, height;
	float *px; /* width*height*4 floats, rows top to bottom */
};

/* A cleared (all zero) framebuffer; NULL if the size is impossible. */
struct framebuffer *fb_new(int width, int height);
void fb_free(struct framebuffer *fb);
static inline float *fb_pixel(struct framebuffer *fb, int x, int y)
{
	return fb->px + ((size_t)y * (size_t)fb->width + (size_t)x) * 4;
}

#endif

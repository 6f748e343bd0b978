/* framebuffer.c: the float framebuffer (see framebuffer.h). */
#include "image/framebuffer.h"

#include <stdint.h>
#include <stdlib.h>

struct framebuffer *fb_new(int width, int height)
{
	if (width <= 0 || height <= 0 || (size_t)width > SIZE_MAX / 16 / (size_t)height)
		return NULL;
	struct framebuffer *fb = malloc(sizeof *fb);
	if (!fb)
		return NULL;
	fb->width = width;
	fb->height = height;
	fb->px = calloc((size_t)width * (size_t)height * 4, sizeof(float));
	if (!fb->px) {
		free(fb);
		return NULL;
	}
	return fb;
}

void fb_free(struct framebuffer *fb)
{
	if (!fb) return;
	free(fb->px);
	free(fb);
}

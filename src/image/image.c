/* image.c: images for image_map, bump_map, image_pattern and material_map
 * (see image.h). IN PROGRESS: being written. */
#include "image/image.h"

#include <stdio.h>
#include <stdlib.h>

struct image *image_load(const char *path, double gamma, char *err, unsigned errsize)
{
	(void)gamma;
	snprintf(err, errsize, "cannot read image '%s'", path);
	return NULL;
}

struct image *image_ref(struct image *img)
{
	if (img)
		img->refs++;
	return img;
}

void image_unref(struct image *img)
{
	if (!img || --img->refs > 0)
		return;
	free((void *)img->path);
	free(img->px);
	free(img->index);
	free(img);
}

bool image_map_eval(const struct image_mapping *m, vec3 q, struct rgbft *out, int *index)
{
	(void)m; (void)q;
	*out = (struct rgbft){0, 0, 0, 0, 1};
	if (index)
		*index = 0;
	return false;
}

double image_map_value(const struct image_mapping *m, vec3 q)
{
	(void)m; (void)q;
	return 0;
}

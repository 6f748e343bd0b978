/* atmos.c: the atmosphere's storage (see atmos.h). */
#include "scene/atmos.h"

#include "scene/texture.h"

#include <stdlib.h>

void atmos_free(struct atmosphere *a)
{
	free(a->fogs);
	if (a->sky) {
		for (size_t i = 0; i < a->sky->npigments; i++)
			pigment_unref(a->sky->pigments[i]);
		free(a->sky->pigments);
		free(a->sky);
	}
	for (size_t i = 0; i < a->nrainbows; i++)
		pigment_unref(a->rainbows[i].color_map);
	free(a->rainbows);
	a->fogs = NULL;
	a->sky = NULL;
	a->rainbows = NULL;
	a->nfogs = a->nrainbows = 0;
}

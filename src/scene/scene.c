/* scene.c: the scene container (see scene.h). */
#include "scene/scene.h"

#include <stdlib.h>

struct scene *scene_new(void)
{
	struct scene *s = calloc(1, sizeof *s);
	if (!s) abort();
	s->camera = camera_default();
	s->gs.assumed_gamma = 1.0;
	s->gs.max_trace_level = 5;
	s->gs.adc_bailout = 1.0 / 255.0;
	s->gs.ambient_light = rgb_make(1, 1, 1);
	s->gs.irid_wavelength = rgb_make(0.25, 0.18, 0.14);
	s->gs.noise_generator = 2;
	s->gs.number_of_waves = 10;
	s->gs.charset = 0; /* ascii, POV-Ray 3.7's default (measured with text) */
	s->background.t = 1; /* POV-Ray 3.7: transparent black until a background statement */
	s->version = 3.7;
	return s;
}

void scene_free(struct scene *s)
{
	if (!s) return;
	for (size_t i = 0; i < s->nobjects; i++)
		object_free(s->objects[i]);
	free(s->objects);
	for (size_t i = 0; i < s->nlights; i++) {
		object_free(s->lights[i].looks_like);
		object_free(s->lights[i].projected_through);
	}
	free(s->lights);
	free(s->groups);
	atmos_free(&s->atmos);
	camera_clear(&s->camera);
	free(s);
}

void scene_add_object(struct scene *s, struct object *o)
{
	if (s->nobjects == s->cap_objects) {
		s->cap_objects = s->cap_objects ? s->cap_objects * 2 : 16;
		s->objects = realloc(s->objects, s->cap_objects * sizeof *s->objects);
		if (!s->objects) abort();
	}
	o->id = (unsigned)s->nobjects;
	s->objects[s->nobjects++] = o;
}

void scene_add_light(struct scene *s, const struct light *l)
{
	if (s->nlights == s->cap_lights) {
		s->cap_lights = s->cap_lights ? s->cap_lights * 2 : 4;
		s->lights = realloc(s->lights, s->cap_lights * sizeof *s->lights);
		if (!s->lights) abort();
	}
	s->lights[s->nlights++] = *l;
}

int scene_add_light_group(struct scene *s, int parent)
{
	if (s->ngroups == 0)
		s->ngroups = 1;
	if (s->ngroups >= s->cap_groups) {
		s->cap_groups = s->cap_groups ? s->cap_groups * 2 : 8;
		s->groups = realloc(s->groups, s->cap_groups * sizeof *s->groups);
		if (!s->groups) abort();
	}
	s->groups[s->ngroups] = (struct light_group){.parent = parent};
	return (int)s->ngroups++;
}

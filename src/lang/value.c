/* value.c: values (see value.h). */
#include "lang/value.h"

#include "lang/lex.h"
#include "scene/atmos.h"
#include "scene/camera.h"
#include "scene/fn.h"
#include "scene/light.h"

#include <stdlib.h>
#include <string.h>

const char *val_kind_name(enum val_kind k)
{
	switch (k) {
	case VAL_NONE: return "nothing";
	case VAL_FLOAT: return "float";
	case VAL_VECTOR: return "vector";
	case VAL_COLOR: return "color";
	case VAL_STRING: return "string";
	case VAL_OBJECT: return "object";
	case VAL_TEXTURE: return "texture";
	case VAL_PIGMENT: return "pigment";
	case VAL_FINISH: return "finish";
	case VAL_NORMAL: return "normal";
	case VAL_INTERIOR: return "interior";
	case VAL_MATERIAL: return "material";
	case VAL_MAP:
		return "map";
	case VAL_CAMERA: return "camera";
	case VAL_LIGHT: return "light_source";
	case VAL_TRANSFORM: return "transform";
	case VAL_MACRO: return "macro";
	case VAL_ALIAS: return "reference";
	case VAL_ARRAY: return "array";
	case VAL_SPLINE: return "spline";
	case VAL_FUNCTION: return "function";
	case VAL_FILE: return "file";
	case VAL_FOG: return "fog";
	case VAL_SKY_SPHERE: return "sky_sphere";
	case VAL_RAINBOW: return "rainbow";
	}
	return "?";
}

void val_clear(struct value *v)
{
	switch (v->kind) {
	case VAL_OBJECT: object_free(v->obj); break;
	case VAL_TEXTURE: texture_unref(v->tex); break;
	case VAL_PIGMENT: pigment_unref(v->pig); break;
	case VAL_FINISH: free(v->fin); break;
	case VAL_NORMAL: normal_unref(v->nrm); break;
	case VAL_INTERIOR: interior_unref(v->interior); break;
	case VAL_MATERIAL:
		texture_unref(v->mat->tex);
		interior_unref(v->mat->interior);
		free(v->mat);
		break;
	case VAL_MAP: blend_map_unref(v->map); break;
	case VAL_CAMERA:
		camera_clear(v->cam);
		free(v->cam);
		break;
	case VAL_LIGHT:
		light_free_parts(v->light);
		free(v->light);
		break;
	case VAL_TRANSFORM: free(v->xf); break;
	case VAL_MACRO:
		if (--v->mac->refs == 0) {
			free(v->mac->params);
			free(v->mac);
		}
		break;
	case VAL_ARRAY:
		if (--v->arr->refs == 0) {
			for (size_t i = 0; i < v->arr->count; i++)
				val_clear(&v->arr->elems[i]);
			free(v->arr->elems);
			free(v->arr);
		}
		break;
	case VAL_SPLINE: spline_unref(v->spl); break;
	case VAL_FUNCTION: fn_unref(v->fn); break;
	case VAL_FILE: sdl_file_unref(v->file); break;
	case VAL_FOG: free(v->fog); break;
	case VAL_SKY_SPHERE: sky_sphere_free(v->sky); break;
	case VAL_RAINBOW:
		rainbow_clear(v->rainbow);
		free(v->rainbow);
		break;
	default: break;
	}
	v->kind = VAL_NONE;
}

static void *dup_bytes(const void *p, size_t n)
{
	void *c = malloc(n);
	if (!c) abort();
	return memcpy(c, p, n);
}

struct value val_copy(const struct value *src)
{
	struct value v = *src;
	switch (src->kind) {
	case VAL_OBJECT: v.obj = object_copy(src->obj); break;
	case VAL_TEXTURE: v.tex = texture_ref(src->tex); break;
	case VAL_PIGMENT: v.pig = pigment_ref(src->pig); break;
	case VAL_FINISH: v.fin = dup_bytes(src->fin, sizeof *src->fin); break;
	case VAL_NORMAL: v.nrm = normal_ref(src->nrm); break;
	case VAL_INTERIOR: v.interior = interior_ref(src->interior); break;
	case VAL_MATERIAL:
		v.mat = dup_bytes(src->mat, sizeof *src->mat);
		texture_ref(v.mat->tex);
		interior_ref(v.mat->interior);
		break;
	case VAL_MAP: v.map = blend_map_ref(src->map); break;
	case VAL_CAMERA:
		v.cam = dup_bytes(src->cam, sizeof *src->cam);
		camera_copy(v.cam, src->cam);
		break;
	case VAL_LIGHT:
		v.light = dup_bytes(src->light, sizeof *src->light);
		light_copy_parts(v.light);
		break;
	case VAL_TRANSFORM: v.xf = dup_bytes(src->xf, sizeof *src->xf); break;
	case VAL_MACRO: v.mac->refs++; break;
	case VAL_ARRAY: v.arr->refs++; break;
	case VAL_SPLINE: v.spl->refs++; break;
	case VAL_FUNCTION: fn_ref(v.fn); break;
	case VAL_FILE: v.file->refs++; break;
	case VAL_FOG: v.fog = dup_bytes(src->fog, sizeof *src->fog); break;
	case VAL_SKY_SPHERE: v.sky = sky_sphere_copy(src->sky); break;
	case VAL_RAINBOW:
		v.rainbow = dup_bytes(src->rainbow, sizeof *src->rainbow);
		if (v.rainbow->color_map)
			blend_map_ref(v.rainbow->color_map);
		break;
	default: break;
	}
	v.owner = 0;
	v.deprecated = NULL;
	return v;
}

struct array *array_new(int ndims, const int *dims)
{
	struct array *a = calloc(1, sizeof *a);
	if (!a) abort();
	a->refs = 1;
	a->ndims = ndims;
	a->count = 1;
	for (int i = 0; i < ndims; i++) {
		a->dims[i] = dims[i];
		a->count *= (size_t)dims[i];
	}
	a->elems = calloc(a->count ? a->count : 1, sizeof *a->elems);
	if (!a->elems) abort();
	return a;
}

struct array *array_unshare(struct value *v)
{
	struct array *a = v->arr;
	if (a->refs == 1)
		return a;
	struct array *c = array_new(a->ndims, a->dims);
	for (size_t i = 0; i < a->count; i++)
		c->elems[i] = val_copy(&a->elems[i]);
	a->refs--;
	v->arr = c;
	return c;
}

void spline_unref(struct spline *s)
{
	if (s && --s->refs == 0) {
		free(s->t);
		free(s->v);
		free(s->d2);
		free(s);
	}
}

void sdl_file_unref(struct sdl_file *f)
{
	if (f && --f->refs == 0) {
		if (f->fp)
			fclose(f->fp);
		free(f);
	}
}

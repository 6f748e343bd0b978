/* light.h: light sources. */
#ifndef LUCENT_LIGHT_H
#define LUCENT_LIGHT_H

#include "lang/source.h"
#include "math/vec.h"
#include "scene/color.h"

#include <stdbool.h>

enum light_kind { LIGHT_POINT };

struct light {
	enum light_kind kind;
	vec3 pos;
	rgb color;
	bool shadowless;
	struct srcpos srcpos;
};

#endif

/* pattern.c: pattern values and their modifiers (see pattern.h). */
#include "pattern/kinds.h"

#include "image/image.h"
#include "scene/fn.h"
#include "scene/object.h"
#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

static const char *const names[PAT__COUNT] = {
	[PAT_NONE] = "none", [PAT_CHECKER] = "checker", [PAT_HEXAGON] = "hexagon", [PAT_BRICK] = "brick",
	[PAT_OBJECT] = "object", [PAT_CUBIC] = "cubic", [PAT_SQUARE] = "square", [PAT_TRIANGULAR] = "triangular",
	[PAT_AGATE] = "agate", [PAT_AOI] = "aoi", [PAT_AVERAGE] = "average", [PAT_BOXED] = "boxed",
	[PAT_BOZO] = "bozo", [PAT_BUMPS] = "bumps", [PAT_CELLS] = "cells", [PAT_CRACKLE] = "crackle",
	[PAT_CYLINDRICAL] = "cylindrical", [PAT_DENTS] = "dents", [PAT_FACETS] = "facets",
	[PAT_FUNCTION] = "function", [PAT_GRADIENT] = "gradient", [PAT_GRANITE] = "granite",
	[PAT_IMAGE] = "image_pattern", [PAT_JULIA] = "julia", [PAT_LEOPARD] = "leopard",
	[PAT_MAGNET] = "magnet", [PAT_MANDEL] = "mandel", [PAT_MARBLE] = "marble", [PAT_ONION] = "onion",
	[PAT_PAVEMENT] = "pavement", [PAT_PIGMENT] = "pigment_pattern", [PAT_PLANAR] = "planar",
	[PAT_QUILTED] = "quilted", [PAT_RADIAL] = "radial", [PAT_RIPPLES] = "ripples",
	[PAT_SLOPE] = "slope", [PAT_SPHERICAL] = "spherical", [PAT_SPIRAL1] = "spiral1",
	[PAT_SPIRAL2] = "spiral2", [PAT_SPOTTED] = "spotted", [PAT_TILING] = "tiling",
	[PAT_WAVES] = "waves", [PAT_WOOD] = "wood", [PAT_WRINKLES] = "wrinkles",
};

const char *pattern_name(enum pattern_kind k)
{
	return k >= 0 && k < PAT__COUNT && names[k] ? names[k] : "?";
}

int pattern_block_entries(enum pattern_kind k)
{
	switch (k) {
	case PAT_CHECKER: case PAT_BRICK: case PAT_OBJECT: return 2;
	case PAT_HEXAGON: return 3;
	case PAT_SQUARE: return 4;
	case PAT_CUBIC: case PAT_TRIANGULAR: return 6;
	default: return 0;
	}
}

bool pattern_is_block(enum pattern_kind k)
{
	return pattern_block_entries(k) > 0;
}

/* The wave type a kind uses when none is written: POV-Ray gives marble,
 * wood, spiral1 and spiral2 a triangle wave (measured: `ramp_wave` changes
 * their function{pattern{}} values, and for no other kind). */
static enum wave_type default_wave(enum pattern_kind k)
{
	switch (k) {
	case PAT_MARBLE: case PAT_WOOD: case PAT_SPIRAL1: case PAT_SPIRAL2: return WAVE_TRIANGLE;
	default: return WAVE_RAMP;
	}
}

struct pattern pattern_make(enum pattern_kind k)
{
	struct pattern pt = PATTERN_INIT_NONE;
	pt.kind = k;
	pt.wave = default_wave(k);
	/* the kinds' own parameters, POV-Ray's defaults (the manual) */
	switch (k) {
	case PAT_BRICK:
		pt.vec = v3(8, 3, 4.5);          /* brick_size */
		pt.vec2 = v3(0.5, 0, 0);         /* mortar */
		break;
	case PAT_QUILTED:
		pt.f[0] = 1.0;                   /* control0 */
		pt.f[1] = 1.0;                   /* control1 */
		break;
	case PAT_AGATE:
		pt.f[0] = 1.0;                   /* agate_turb */
		break;
	case PAT_CRACKLE:
		pt.form = v3(-1, 1, 0);
		pt.f[0] = 2.0;                   /* metric */
		pt.f[1] = 0.0;                   /* offset */
		break;
	case PAT_FACETS:
		pt.vec = v3(0.1, 0, 0);          /* size, coords */
		pt.f[0] = 2.0;                   /* metric */
		break;
	case PAT_GRADIENT:
		pt.vec = v3(1, 0, 0);
		break;
	case PAT_SLOPE:
		pt.vec = v3(0, 1, 0);
		pt.f[0] = 0.0; pt.f[1] = 1.0;   /* slope low, high */
		pt.f[2] = 0.0; pt.f[3] = 0.0;   /* altitude low, high (none) */
		break;
	case PAT_SPIRAL1: case PAT_SPIRAL2:
		pt.n[0] = 1;                     /* arms (the syntax requires them) */
		break;
	case PAT_JULIA: case PAT_MANDEL: case PAT_MAGNET:
		pt.fractal.iterations = 20;
		pt.fractal.exponent = 2;
		pt.fractal.magnet_type = 1;
		pt.fractal.interior_type = 0;
		pt.fractal.exterior_type = 1;
		pt.fractal.interior_factor = 1.0;
		pt.fractal.exterior_factor = 1.0;
		break;
	case PAT_TILING:
		pt.n[0] = 1;                     /* tiling type */
		break;
	case PAT_PAVEMENT:
		pt.n[0] = 3;                     /* number_of_sides */
		pt.n[1] = 1;                     /* number_of_tiles */
		pt.n[2] = 1;                     /* pattern */
		break;
	default:
		break;
	}
	return pt;
}

struct pattern pattern_copy(const struct pattern *src)
{
	struct pattern c = *src;
	if (src->nops) {
		c.ops = malloc((size_t)src->nops * sizeof *c.ops);
		if (!c.ops) abort();
		memcpy(c.ops, src->ops, (size_t)src->nops * sizeof *c.ops);
	}
	if (c.fn)
		fn_ref(c.fn);
	if (c.obj)
		c.obj = object_copy(src->obj);
	if (c.pig)
		pigment_ref(c.pig);
	if (c.img.img)
		image_ref(c.img.img);
	if (src->img.nentry) {
		size_t sz = (size_t)src->img.nentry * sizeof *c.img.entry;
		c.img.entry = malloc(sz);
		if (!c.img.entry) abort();
		memcpy(c.img.entry, src->img.entry, sz);
	}
	return c;
}

void pattern_clear(struct pattern *pt)
{
	free(pt->ops);
	if (pt->fn)
		fn_unref(pt->fn);
	if (pt->obj)
		object_free(pt->obj);
	pigment_unref(pt->pig);
	image_unref(pt->img.img);
	free(pt->img.entry);
	*pt = pattern_make(PAT_NONE);
}

void pattern_add_op(struct pattern *pt, const struct pattern_op *op)
{
	struct pattern_op *ops = realloc(pt->ops, (size_t)(pt->nops + 1) * sizeof *ops);
	if (!ops) abort();
	pt->ops = ops;
	pt->ops[pt->nops++] = *op;
}

void pattern_transform(struct pattern *pt, const struct xform *t)
{
	if (pt->uv_mapping)
		return;
	if (pt->nops && pt->ops[pt->nops - 1].kind == POP_TRANSFORM) {
		struct pattern_op *last = &pt->ops[pt->nops - 1];
		last->xf = xform_compose(t, &last->xf);
		return;
	}
	struct pattern_op op;
	memset(&op, 0, sizeof op);
	op.kind = POP_TRANSFORM;
	op.xf = *t;
	pattern_add_op(pt, &op);
}

void pattern_prepare(struct pattern *pt)
{
	if (pt->obj)
		object_prepare(pt->obj);
}

double pattern_raw(const struct pattern *pt, vec3 q, const struct pattern_ctx *ctx)
{
	switch (pt->kind) {
	case PAT_NONE: case PAT_AVERAGE: case PAT__COUNT: return 0;
	case PAT_CHECKER: return pat_checker(pt, q, ctx);
	case PAT_HEXAGON: return pat_hexagon(pt, q, ctx);
	case PAT_BRICK: return pat_brick(pt, q, ctx);
	case PAT_OBJECT: return pat_object(pt, q, ctx);
	case PAT_CUBIC: return pat_cubic(pt, q, ctx);
	case PAT_SQUARE: return pat_square(pt, q, ctx);
	case PAT_TRIANGULAR: return pat_triangular(pt, q, ctx);
	case PAT_AGATE: return pat_agate(pt, q, ctx);
	case PAT_AOI: return pat_aoi(pt, q, ctx);
	case PAT_BOXED: return pat_boxed(pt, q, ctx);
	case PAT_BOZO: return pat_bozo(pt, q, ctx);
	case PAT_BUMPS: return pat_bumps(pt, q, ctx);
	case PAT_CELLS: return pat_cells(pt, q, ctx);
	case PAT_CRACKLE: return pat_crackle(pt, q, ctx);
	case PAT_CYLINDRICAL: return pat_cylindrical(pt, q, ctx);
	case PAT_DENTS: return pat_dents(pt, q, ctx);
	case PAT_FACETS: return pat_facets(pt, q, ctx);
	case PAT_FUNCTION: return pat_function(pt, q, ctx);
	case PAT_GRADIENT: return pat_gradient(pt, q, ctx);
	case PAT_GRANITE: return pat_granite(pt, q, ctx);
	case PAT_IMAGE: return pat_image(pt, q, ctx);
	case PAT_JULIA: return pat_julia(pt, q, ctx);
	case PAT_LEOPARD: return pat_leopard(pt, q, ctx);
	case PAT_MAGNET: return pat_magnet(pt, q, ctx);
	case PAT_MANDEL: return pat_mandel(pt, q, ctx);
	case PAT_MARBLE: return pat_marble(pt, q, ctx);
	case PAT_ONION: return pat_onion(pt, q, ctx);
	case PAT_PAVEMENT: return pat_pavement(pt, q, ctx);
	case PAT_PIGMENT: return pat_pigment(pt, q, ctx);
	case PAT_PLANAR: return pat_planar(pt, q, ctx);
	case PAT_QUILTED: return pat_quilted(pt, q, ctx);
	case PAT_RADIAL: return pat_radial(pt, q, ctx);
	case PAT_RIPPLES: return pat_ripples(pt, q, ctx);
	case PAT_SLOPE: return pat_slope(pt, q, ctx);
	case PAT_SPHERICAL: return pat_spherical(pt, q, ctx);
	case PAT_SPIRAL1: return pat_spiral1(pt, q, ctx);
	case PAT_SPIRAL2: return pat_spiral2(pt, q, ctx);
	case PAT_SPOTTED: return pat_spotted(pt, q, ctx);
	case PAT_TILING: return pat_tiling(pt, q, ctx);
	case PAT_WAVES: return pat_waves(pt, q, ctx);
	case PAT_WOOD: return pat_wood(pt, q, ctx);
	case PAT_WRINKLES: return pat_wrinkles(pt, q, ctx);
	}
	return 0;
}

/* Frequency, phase and the wave type applied to a continuous pattern's raw
 * value v, as POV-Ray does it (every step measured with function{pattern{}}):
 * unless the frequency is 0 (which turns frequency and phase off),
 * v*frequency + phase is reduced modulo 1.00001, not 1, so that 1 survives
 * (gradient x at x = 1 gives 1, frequency 2 at x = 1 gives 0.99999); a
 * negative result is then moved into [0, 1) by its floor. Frequency and
 * phase are single-precision numbers in POV-Ray: `phase 0.3` adds
 * 0.300000011920929. */
static double apply_wave(const struct pattern *pt, double v)
{
	float freq = (float)pt->frequency;
	if (freq != 0.0f)
		v = fmod(v * freq + (float)pt->phase, 1.00001);
	if (v < 0.0)
		v -= floor(v);
	switch (pt->wave) {
	case WAVE_RAMP:
		break;
	case WAVE_TRIANGLE:
		v *= 2.0;
		if (v > 1.0)
			v = 2.0 - v;
		break;
	case WAVE_SINE:
		v = (sin(v * (2.0 * PI)) + 1.0) * 0.5;
		break;
	case WAVE_SCALLOP:
		v = fabs(sin(v * PI));
		break;
	case WAVE_CUBIC:
		v = v * v * (3.0 - 2.0 * v);
		break;
	case WAVE_POLY:
		v = pow(v, (float)pt->wave_exponent);   /* single precision too */
		break;
	}
	return v;
}

double pattern_wave(const struct pattern *pt, double v)
{
	return apply_wave(pt, v);
}

double pattern_value(const struct pattern *pt, const struct pattern_ctx *ctx)
{
	vec3 q = pattern_point(pt, ctx->p);
	double v = pattern_raw(pt, q, ctx);
	if (pattern_is_block(pt->kind))
		return v;
	return apply_wave(pt, v);
}

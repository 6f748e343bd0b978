/* atmos.c: background, sky_sphere, fog and rainbows on rays (see atmos.h).
 * Every formula here was measured on POV-Ray 3.7 with flat scenes (an
 * emitting plane at known distances, 16-bit linear output): the figures
 * are in tests/render/atmos.list and doc/rendering.md. */
#include "render/atmos.h"

#include "math/hash.h"
#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* POV-Ray's grey of a colour, the share of a filter that passes transmit. */
static double gray(struct rgbft c)
{
	return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

struct rgbft atmos_escape(const struct prepared *p, vec3 dir)
{
	const struct scene *sc = p->scene;
	struct rgbft bg = sc->background;
	/* The background over black: its colour counts by its opacity. */
	double o = 1 - bg.t;
	struct rgbft below = {bg.r * o, bg.g * o, bg.b * o, 0, bg.t};
	const struct sky_sphere *sky = sc->atmos.sky;
	if (!(p->features & FEAT_SKY) || !sky)
		return below;
	/* The layers from the top down: each adds its colour times its
	 * opacity, filtered by the layers above it, and lets through
	 * filter * colour + transmit of what is under it (POV-Ray 3.7's rule,
	 * that of a layered texture). The emission scales the sky's own
	 * colour, not the background seen through it (measured). */
	vec3 q = mat_point(&sky->xf.inv, dir);
	struct pattern_ctx ctx = {.p = q, .normal = v3_neg(dir), .dir = dir,
	                          .noise_generator = sc->gs.noise_generator, .number_of_waves = sc->gs.number_of_waves};
	rgb acc = rgb_make(0, 0, 0), pass = rgb_make(1, 1, 1);
	double tpass = 1;
	for (size_t i = sky->npigments; i-- > 0;) {
		struct rgbft c = pigment_eval(sky->pigments[i], &ctx);
		double op = 1 - c.f - c.t;
		acc = rgb_add(acc, rgb_mul(pass, rgb_make(c.r * op, c.g * op, c.b * op)));
		pass = rgb_mul(pass, rgb_make(c.f * c.r + c.t, c.f * c.g + c.t, c.f * c.b + c.t));
		tpass *= c.f * gray(c) + c.t;
		if (rgb_max(pass) <= 0 && tpass <= 0)
			break;
	}
	acc = rgb_mul(acc, sky->emission);
	return (struct rgbft){acc.r + pass.r * below.r, acc.g + pass.g * below.g, acc.b + pass.b * below.b, 0,
	                      tpass * below.t};
}

/* The colour of map m at v, all five channels interpolated. */
static struct rgbft map_color(const struct blend_map *m, double v)
{
	int lo, hi;
	double w;
	blend_map_find(m, v, &lo, &hi, &w);
	struct rgbft a = m->e[lo].color, b = m->e[hi].color;
	return (struct rgbft){a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w, a.f + (b.f - a.f) * w,
	                      a.t + (b.t - a.t) * w};
}

/* What a haze of colour h that lets k of what is behind it through does:
 * what is behind is multiplied by pass (rgb) and tpass (its transmit), and
 * add is the haze's own colour. h's transmit is the least share that gets
 * through; its filter tints what gets through (measured). */
struct veil {
	rgb pass, add;
	double tpass;
};

static struct veil veil_of(struct rgbft h, double k, bool rainbow)
{
	if (k < h.t)
		k = h.t;
	/* A fog's filter tints all that gets through; a rainbow's only the
	 * share it hides (measured: 1 - f + f*colour against
	 * 1 - f*(1-k)*(1 - colour)). */
	double f = rainbow ? h.f * (1 - k) : h.f;
	struct veil v;
	v.pass = rgb_make(k * (1 - f + f * h.r), k * (1 - f + f * h.g), k * (1 - f + f * h.b));
	v.tpass = k * (1 - f + f * gray(h));
	v.add = rgb_make((1 - k) * h.r, (1 - k) * h.g, (1 - k) * h.b);
	return v;
}

static struct rgbft veil_apply(const struct veil *v, struct rgbft c)
{
	return (struct rgbft){v->pass.r * c.r + v->add.r, v->pass.g * c.g + v->add.g, v->pass.b * c.b + v->add.b, c.f,
	                      v->tpass * c.t};
}

/* The rainbow's contribution: c seen through rainbow rb along dir. */
static struct rgbft rainbow_apply(const struct rainbow *rb, vec3 org, vec3 dir, double depth, struct rgbft c)
{
	if (!rb->color_map || rb->color_map->n == 0 || rb->width <= 0 || rb->distance <= 0)
		return c;
	vec3 d = v3_norm(rb->direction);
	double cosa = v3_dot(dir, d);
	cosa = cosa > 1 ? 1 : cosa < -1 ? -1 : cosa;
	double angle = acos(cosa) * (180 / M_PI);
	double idx = (angle - (rb->angle - rb->width / 2)) / rb->width;
	if (rb->jitter != 0) {
		/* A deterministic draw per ray, from its origin and direction. */
		uint64_t bits[4];
		memcpy(&bits[0], &dir.x, 8);
		memcpy(&bits[1], &dir.y, 8);
		memcpy(&bits[2], &dir.z, 8);
		memcpy(&bits[3], &org.x, 8);
		uint64_t h = hash_mix(bits[0] ^ hash_mix(bits[1] ^ hash_mix(bits[2] ^ hash_mix(bits[3]))));
		double u = (double)(h >> 11) * (1.0 / 9007199254740992.0);
		idx += rb->jitter * (u - 0.5);
	}
	if (idx < 0 || idx > 1)
		return c;
	struct rgbft col = map_color(rb->color_map, idx);
	if (rb->arc_angle < 360) {
		/* The angle around the direction, from up (measured: the arc is
		 * cut at +-arc_angle/2 and fades out by 3x^2 - 2x^3 beyond
		 * +-falloff_angle/2, by raising the colour's transmit). */
		vec3 up = v3_sub(rb->up, v3_scale(d, v3_dot(rb->up, d)));
		vec3 side = v3_sub(dir, v3_scale(d, cosa));
		double lu = v3_len(up), ls = v3_len(side);
		double ca = lu > 0 && ls > 0 ? v3_dot(up, side) / (lu * ls) : 1;
		ca = ca > 1 ? 1 : ca < -1 ? -1 : ca;
		double theta = acos(ca) * (180 / M_PI);
		double a2 = rb->arc_angle / 2, f2 = rb->falloff_angle / 2;
		if (theta > a2)
			return c;
		if (theta > f2) {
			double x = (a2 - theta) / (a2 - f2);
			double fall = x * x * (3 - 2 * x);
			col.t = 1 - (1 - col.t) * fall;
		}
	}
	struct veil v = veil_of(col, exp(-depth / rb->distance), true);
	return veil_apply(&v, c);
}

/* How much of what lies behind fog f gets through the segment. */
static double fog_attenuation(const struct fog *f, vec3 org, vec3 dir, double depth, int generator)
{
	double width = depth;
	if (f->type == FOG_GROUND) {
		/* The density is 1 up to fog_offset and 1/(1+((h-offset)/alt)^2)
		 * above it (measured: an arctangent profile, not the manual's
		 * 1/(1+(h-offset)/alt)^2); the segment gets its mean between
		 * the heights of its ends. */
		vec3 up = f->up;
		double lu = v3_len(up);
		up = lu > 0 ? v3_scale(up, 1 / lu) : up;
		double h0 = v3_dot(org, up), h1 = v3_dot(v3_madd(org, dir, depth), up);
		double off = f->offset, alt = f->alt;
#define GROUND_INTEGRAL(h) ((h) <= off ? (h) - off : alt > 0 ? alt * atan(((h) - off) / alt) : 0)
		double dens;
		if (fabs(h1 - h0) > 1e-12 * (1 + fabs(h0)))
			dens = (GROUND_INTEGRAL(h1) - GROUND_INTEGRAL(h0)) / (h1 - h0);
		else if (h0 <= off)
			dens = 1;
		else
			dens = alt > 0 ? 1 / (1 + ((h0 - off) / alt) * ((h0 - off) / alt)) : 0;
#undef GROUND_INTEGRAL
		width = depth * dens;
	}
	if (!f->has_turbulence)
		return exp(-width / f->distance);
	/* Turbulence thins the fog (measured on POV-Ray 3.7): with T the
	 * scalar turbulence at the segment's midpoint scaled component-wise
	 * by the turbulence amount (the fog's transformations do not move
	 * it), and w = min(1, 2 * turb_depth * T), the width shrinks by the
	 * factor 1 - w * exp(-depth / distance), for both fog types. */
	vec3 q = v3_madd(org, dir, depth / 2);
	q = v3(q.x * f->turb.amount.x, q.y * f->turb.amount.y, q.z * f->turb.amount.z);
	double w = 2 * f->turb_depth * turbulence1(q, &f->turb, generator);
	w = w > 1 ? 1 : w;
	return exp(-width * (1 - w * exp(-depth / f->distance)) / f->distance);
}

struct rgbft atmos_apply(const struct prepared *p, const struct medium *med, vec3 org, vec3 dir, double depth,
                         struct rgbft c)
{
	const struct scene *sc = p->scene;
	const struct atmosphere *a = &sc->atmos;
	if (med && med->solid)
		return c;
	if (p->features & FEAT_RAINBOW)
		for (size_t i = 0; i < a->nrainbows; i++)
			c = rainbow_apply(&a->rainbows[i], org, dir, depth, c);
	if (!(p->features & FEAT_FOG))
		return c;
	/* Fogs act together (measured): what is behind is dimmed and tinted
	 * by every fog, and each fog adds its own colour by the share it
	 * hides; no fog dims another's colour. */
	struct veil all = {rgb_make(1, 1, 1), rgb_make(0, 0, 0), 1};
	for (size_t i = 0; i < a->nfogs; i++) {
		const struct fog *f = &a->fogs[i];
		if (f->distance <= 0)
			continue;
		struct veil v = veil_of(f->color, fog_attenuation(f, org, dir, depth, sc->gs.noise_generator), false);
		all.pass = rgb_mul(all.pass, v.pass);
		all.tpass *= v.tpass;
		all.add = rgb_add(all.add, v.add);
	}
	return veil_apply(&all, c);
}

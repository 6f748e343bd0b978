/* color.h: colours. Lighting is done on three-channel `rgb` values in the
 * working (linear, when assumed_gamma is 1) space; pigments carry POV-Ray's
 * five components: red, green, blue, filter, transmit. */
#ifndef LUCENT_COLOR_H
#define LUCENT_COLOR_H

typedef struct rgb {
	double r, g, b;
} rgb;

struct rgbft {
	double r, g, b, f, t;
};

static inline rgb rgb_make(double r, double g, double b) { rgb c = {r, g, b}; return c; }
static inline rgb rgb_add(rgb a, rgb b) { return rgb_make(a.r + b.r, a.g + b.g, a.b + b.b); }
static inline rgb rgb_mul(rgb a, rgb b) { return rgb_make(a.r * b.r, a.g * b.g, a.b * b.b); }
static inline rgb rgb_scale(rgb a, double s) { return rgb_make(a.r * s, a.g * s, a.b * s); }
static inline rgb rgb_of(struct rgbft c) { return rgb_make(c.r, c.g, c.b); }
static inline double rgb_max(rgb a) { return a.r > a.g ? (a.r > a.b ? a.r : a.b) : (a.g > a.b ? a.g : a.b); }

#endif

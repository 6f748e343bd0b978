/* pattern.h: POV-Ray's patterns, the functions of space that pigments,
 * normals and textures look up in their maps, with their modifiers (wave
 * type, frequency, phase, turbulence, warps, transformations).
 *
 * A pattern is a plain value embedded in the pigment, normal or texture
 * that uses it; what it refers to (a user function, an object, an image, a
 * pigment) is reference-counted or owned, and pattern_copy/pattern_clear
 * manage it.
 *
 * Evaluation: pattern_value(pt, ctx) carries the point ctx->p (world space,
 * or (u, v, 0) under uv_mapping) into pattern space through the ops (warps
 * and transformations, undone from the last declared to the first), then
 * computes the kind's raw value, then applies frequency, phase and the wave
 * type. Continuous patterns give a value in [0, 1] that a map looks up;
 * block patterns (checker, hexagon, brick, object, cubic, square,
 * triangular) give the index of the entry that is chosen. */
#ifndef LUCENT_PATTERN_H
#define LUCENT_PATTERN_H

#include "math/mat.h"
#include "math/vec.h"

#include <stdbool.h>

struct fn;
struct object;
struct image;
struct pigment;

enum pattern_kind {
	PAT_NONE = 0,   /* no pattern: a solid colour, a plain texture */
	/* block patterns: the value is an entry index */
	PAT_CHECKER, PAT_HEXAGON, PAT_BRICK, PAT_OBJECT, PAT_CUBIC, PAT_SQUARE, PAT_TRIANGULAR,
	/* continuous patterns: the value in [0, 1] is looked up in a map */
	PAT_AGATE, PAT_AOI, PAT_AVERAGE, PAT_BOXED, PAT_BOZO, PAT_BUMPS, PAT_CELLS, PAT_CRACKLE,
	PAT_CYLINDRICAL, PAT_DENTS, PAT_FACETS, PAT_FUNCTION, PAT_GRADIENT, PAT_GRANITE, PAT_IMAGE,
	PAT_JULIA, PAT_LEOPARD, PAT_MAGNET, PAT_MANDEL, PAT_MARBLE, PAT_ONION, PAT_PAVEMENT,
	PAT_PIGMENT, PAT_PLANAR, PAT_QUILTED, PAT_RADIAL, PAT_RIPPLES, PAT_SLOPE, PAT_SPHERICAL,
	PAT_SPIRAL1, PAT_SPIRAL2, PAT_SPOTTED, PAT_TILING, PAT_WAVES, PAT_WOOD, PAT_WRINKLES,
	PAT__COUNT
};

/* The keyword of a kind ("checker"), for messages and docs. */
const char *pattern_name(enum pattern_kind k);
/* Block patterns choose an entry (pattern_value is its index). */
bool pattern_is_block(enum pattern_kind k);
/* How many entries a block pattern's list takes (checker 2, hexagon 3,
 * brick 2, object 2, cubic 6, square 4, triangular 6); 0 otherwise. */
int pattern_block_entries(enum pattern_kind k);

enum wave_type { WAVE_RAMP, WAVE_TRIANGLE, WAVE_SINE, WAVE_SCALLOP, WAVE_CUBIC, WAVE_POLY };

/* Turbulence parameters (classic `turbulence` and `warp { turbulence }`). */
struct turbulence {
	vec3 amount;
	int octaves;       /* 6 */
	double omega;      /* 0.5 */
	double lambda;     /* 2.0 */
};

enum pattern_op_kind {
	POP_TRANSFORM,     /* xf: pattern_from_outer is xf.inv */
	POP_TURBULENCE,    /* warp { turbulence } */
	POP_REPEAT,        /* warp { repeat V offset V flip V } */
	POP_BLACK_HOLE,    /* warp { black_hole C, R falloff strength inverse repeat turbulence } */
	POP_CYLINDRICAL,   /* warp { cylindrical orientation V dist_exp F } */
	POP_SPHERICAL,     /* warp { spherical orientation V dist_exp F } */
	POP_TOROIDAL,      /* warp { toroidal orientation V dist_exp F major_radius F } */
	POP_PLANAR,        /* warp { planar V, offset } */
	POP_CUBIC,         /* warp { cubic } */
};

/* One warp or transformation, in declaration order. */
struct pattern_op {
	enum pattern_op_kind kind;
	struct xform xf;             /* POP_TRANSFORM */
	struct turbulence turb;      /* POP_TURBULENCE; POP_BLACK_HOLE's own turbulence */
	vec3 v1, v2, v3;             /* repeat: width, offset, flip; black_hole: centre, repeat, turbulence amount;
	                              * mapping warps: orientation; planar: normal */
	double f1, f2, f3, f4;       /* black_hole: radius, falloff, strength, inverse;
	                              * mapping warps: dist_exp, major_radius; planar: offset */
};

/* The fractal patterns' parameters (julia, mandel, magnet). */
struct fractal {
	int iterations;
	int exponent;                /* 2..33 */
	int magnet_type;             /* magnet: 1 or 2 */
	bool julia;                  /* magnet: the julia form (c is its constant), not mandel */
	double c[2];                 /* julia: the complex constant */
	int interior_type, exterior_type;
	double interior_factor, exterior_factor;
};

/* How an image is laid on space or on uv (image_map, bump_map,
 * image_pattern, material_map). */
struct image_mapping {
	struct image *img;           /* one reference */
	int map_type;                /* 0 planar, 1 spherical, 2 cylindrical, 5 torus */
	int interpolate;             /* 0 none, 2 bilinear, 4 normalized distance */
	bool once;
	bool use_alpha;              /* image_pattern use_alpha; bump_map use_index/use_color */
	bool use_color;              /* bump_map: use the colour's intensity, not the palette index */
	double filter_all, transmit_all;
	bool has_filter_all, has_transmit_all;
	int nentry;                  /* per-palette-entry filter/transmit overrides */
	struct { int index; double filter, transmit; bool has_filter, has_transmit; } *entry; /* owned */
	double gamma;                /* 0: the file's own; IMAGE_GAMMA_SRGB (-1): `gamma srgb` */
	double major_radius;         /* map_type 5 (POV-Ray's block has no keyword for it: 0 means 1) */
	bool use_index;              /* bump_map use_index: the palette index is the height */
	int premultiplied;           /* -1 the format's own, 0 straight alpha, 1 associated alpha */
};

struct pattern {
	enum pattern_kind kind;

	/* parameters of the kind (unused ones are zero) */
	vec3 vec;                    /* gradient direction; brick size; slope direction; facets: (size, coords, 0) */
	vec3 vec2;                   /* brick: (mortar, 0, 0); slope: altitude direction */
	double f[6];                 /* agate_turb; crackle metric/offset; facets metric; quilted control0/1; slope low/high, alt low/high */
	vec3 form;                   /* crackle form */
	int n[6];                    /* spiral arms; tiling type; pavement sides/tiles/pattern/exterior/interior/form; crackle solid */
	struct fractal fractal;
	struct fn *fn;               /* PAT_FUNCTION: one reference; called with (x, y, z) */
	struct object *obj;          /* PAT_OBJECT: owned, prepared when the pattern is */
	struct pigment *pig;         /* PAT_PIGMENT: one reference; value = its grey */
	struct image_mapping img;    /* PAT_IMAGE (image_pattern, image_map, bump_map) */

	/* modifiers */
	enum wave_type wave;         /* default: the kind's own (ramp for most) */
	double wave_exponent;        /* poly_wave */
	double frequency;            /* 1 */
	double phase;                /* 0 */
	bool has_turbulence;         /* classic `turbulence` written in the pigment/normal */
	struct turbulence turb;
	struct pattern_op *ops;      /* owned; nops entries, declaration order */
	int nops;
	int noise_generator;         /* 0: global_settings' (default 2); 1..3 */
	bool uv_mapping;             /* evaluate at (u, v, 0) */
};

/* What pattern_value may need besides the point. */
struct pattern_ctx {
	vec3 p;                      /* the point: world space, or (u, v, 0) with uv_mapping */
	vec3 normal;                 /* unit surface normal, world space (slope, aoi, facets) */
	vec3 dir;                    /* unit ray direction (aoi) */
	int noise_generator;         /* global_settings { noise_generator }: 1..3 (default 2) */
	int number_of_waves;         /* global_settings { number_of_waves }: 0 means the default, 10 */
};

/* The initialiser of a PAT_NONE pattern with POV-Ray's defaults for the
 * modifiers (what pattern_make(PAT_NONE) returns), for static templates
 * of the structs that hold a pattern. */
#define PATTERN_INIT_NONE                                                       \
	{                                                                       \
		.kind = PAT_NONE, .wave = WAVE_RAMP, .wave_exponent = 1.0,      \
		.frequency = 1.0, .turb = {.octaves = 6, .omega = 0.5, .lambda = 2.0}, \
	}

/* A pattern of kind k with POV-Ray's defaults for its modifiers. */
struct pattern pattern_make(enum pattern_kind k);
/* A copy that shares or copies what src refers to. */
struct pattern pattern_copy(const struct pattern *src);
/* Release what the pattern refers to; it becomes PAT_NONE. */
void pattern_clear(struct pattern *pt);
/* Append a transformation (composed into the last op when that is also a
 * transformation). A pattern already under uv_mapping is left as it is:
 * its point is fixed to the surface, and POV-Ray ignores transformations
 * applied after the uv_mapping block (an object's, a later texture's). */
void pattern_transform(struct pattern *pt, const struct xform *t);
/* Append a warp. */
void pattern_add_op(struct pattern *pt, const struct pattern_op *op);
/* Prepare what the pattern refers to before rendering (PAT_OBJECT). */
void pattern_prepare(struct pattern *pt);

/* The point in pattern space: ctx->p carried through the ops. */
vec3 pattern_point(const struct pattern *pt, vec3 p);
/* The same with the scene's noise generator (ctx->noise_generator) for
 * the turbulence warps, where the pattern has none of its own. */
vec3 pattern_point_ctx(const struct pattern *pt, vec3 p, const struct pattern_ctx *ctx);
/* A world-space normal carried into pattern space through the pattern's
 * transformations (the warps leave it alone), and a pattern-space normal
 * back (neither made unit); a pattern-space direction carried to world
 * space. */
vec3 pattern_normal_in(const struct pattern *pt, vec3 n);
vec3 pattern_normal_out(const struct pattern *pt, vec3 n);
vec3 pattern_dir_out(const struct pattern *pt, vec3 d);
/* The pattern's value at ctx: an index for block patterns, [0, 1] for the
 * others (after frequency, phase and wave type). */
double pattern_value(const struct pattern *pt, const struct pattern_ctx *ctx);
/* pattern_value at world point p with the point moved by off in pattern
 * space, after the transformations and warps, the classic turbulence of
 * the kinds that warp the point with it included (the numerical slope of
 * normals samples there). */
double pattern_value_moved(const struct pattern *pt, vec3 p, vec3 off, const struct pattern_ctx *ctx);
/* Frequency, phase and the wave type applied to a raw value v of pt's
 * kind (what pattern_value does after pattern_raw for continuous kinds). */
double pattern_wave(const struct pattern *pt, double v);
/* The raw value of the kind at pattern-space point q, before frequency,
 * phase and the wave (used by pattern_value and by the normal code). */
double pattern_raw(const struct pattern *pt, vec3 q, const struct pattern_ctx *ctx);

/* How many polyforms `pavement` has for cells of the given number of sides
 * (3, 4, 6) joined in tiles of `tiles` cells: the range of its `pattern`;
 * 0 for a combination that POV-Ray refuses (pavement.c). */
int pavement_pattern_count(int sides, int tiles);

/* ---- noise (noise.c) ---- */

/* POV-Ray's noise: a smooth pseudo-random function of space in [0, 1]
 * with mean 0.5, by generator 1 (original), 2 (range corrected) or 3
 * (Perlin's gradient noise). */
double noise3(vec3 p, int generator);
/* Its vector form, each component in [-1, 1] (turbulence, bumps): the
 * same for every generator, as POV-Ray's. */
vec3 dnoise3(vec3 p, int generator);
/* Turbulence: the sum of octaves of |noise| (scalar) or of dnoise (vector). */
double turbulence1(vec3 p, const struct turbulence *t, int generator);
vec3 turbulence3(vec3 p, const struct turbulence *t, int generator);

#endif

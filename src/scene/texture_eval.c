/* texture_eval.c: evaluating pigments and normals at a point (see
 * texture.h): solid colours, patterns looked up in colour and pigment maps
 * (or POV-Ray's built-in map of the kind when none is given), block
 * patterns choosing an entry by index, image maps, average; normals from
 * the special perturbations, the numerical slope of any pattern, slope
 * maps, normal maps, block patterns of normals and average.
 *
 * The built-in maps were read off POV-Ray 3.7 by printing
 * function { pigment { KIND } } beside function { pattern { KIND } } at
 * hundreds of points. POV-Ray keeps colours in single precision; the
 * blended colour is rounded to float the same way so that values match
 * to the last digit it prints. */
#include "scene/texture.h"

#include "image/image.h"
#include "pattern/kinds.h"

#include <math.h>
#include <stddef.h>

/* ---- built-in colour maps ---- */

struct builtin_entry {
	double v;
	float r, g, b;
};

struct builtin_map {
	int n;
	const struct builtin_entry *e;
};

#define BMAP(name, ...)                                                                 \
	static const struct builtin_entry name##_e[] = {__VA_ARGS__};                    \
	static const struct builtin_map name = {(int)(sizeof name##_e / sizeof name##_e[0]), name##_e}

BMAP(map_grey, {0.0, 0, 0, 0}, {1.0, 1, 1, 1});
BMAP(map_agate, {0.0, 1, 1, 1}, {0.5, 0.95f, 0.75f, 0.5f}, {0.5, 0.9f, 0.7f, 0.5f},
     {0.6, 0.9f, 0.7f, 0.4f}, {0.6, 1.0f, 0.7f, 0.4f}, {1.0, 0.6f, 0.3f, 0.0f});
BMAP(map_bozo, {0.0, 1, 1, 1}, {0.4, 1, 1, 1}, {0.4, 0, 1, 0}, {0.6, 0, 1, 0}, {0.6, 0, 0, 1},
     {0.8, 0, 0, 1}, {0.8, 1, 0, 0}, {1.0, 1, 0, 0});
BMAP(map_marble, {0.0, 0.9f, 0.8f, 0.8f}, {0.9, 0.9f, 0.08f, 0.08f}, {0.9, 0, 0, 0}, {1.0, 0, 0, 0});
BMAP(map_wood, {0.6, 0.666f, 0.312f, 0.2f}, {0.6, 0.4f, 0.1333f, 0.066f}, {1.0, 0.4f, 0.1333f, 0.066f});
BMAP(map_radial, {0.0, 0, 1, 1}, {0.333, 1, 1, 0}, {0.666, 1, 0, 1}, {1.0, 0, 1, 1});
BMAP(map_mandel, {0.001, 0, 0, 0}, {0.001, 0, 1, 1}, {0.012, 1, 1, 0}, {0.015, 1, 0, 1}, {0.1, 0, 1, 1});

/* Block patterns' colours for the entries a scene does not write (measured
 * with function { pigment { ... } }). */
static const float block_blue[3] = {0, 0, 1}, block_green[3] = {0, 1, 0}, block_red[3] = {1, 0, 0};
static const float *const list_checker[] = {block_blue, block_green};
static const float *const list_hexagon[] = {block_blue, block_green, block_red};
static const float brick_mortar[3] = {0.5f, 0.5f, 0.5f}, brick_red[3] = {0.6f, 0.15f, 0.15f};
static const float *const list_brick[] = {brick_mortar, brick_red};
static const float c_yellow[3] = {1, 1, 0}, c_cyan[3] = {0, 1, 1}, c_magenta[3] = {1, 0, 1};
static const float *const list_cubic[] = {block_red, block_green, block_blue, c_yellow, c_cyan, c_magenta};
/* square and triangular: measured in POV-Ray 3.7.0 (function { pigment { square } }) */
static const float *const list_square[] = {block_red, block_green, block_blue, c_yellow};
static const float *const list_triangular[] = {block_red, block_green, block_blue, c_yellow, c_cyan, c_magenta};

static const struct builtin_map *builtin_map(enum pattern_kind k)
{
	switch (k) {
	case PAT_AGATE: return &map_agate;
	case PAT_BOZO: return &map_bozo;
	case PAT_MARBLE: return &map_marble;
	case PAT_WOOD: return &map_wood;
	case PAT_RADIAL: return &map_radial;
	case PAT_MANDEL: return &map_mandel;
	default: return &map_grey;
	}
}

static struct rgbft rgbft_of(const float *c)
{
	struct rgbft r = {c[0], c[1], c[2], 0, 0};
	return r;
}

struct rgbft pattern_block_default(enum pattern_kind k, int i)
{
	const float *const *list;
	switch (k) {
	case PAT_CHECKER: case PAT_OBJECT: list = list_checker; break;
	case PAT_HEXAGON: list = list_hexagon; break;
	case PAT_BRICK: list = list_brick; break;
	case PAT_CUBIC: list = list_cubic; break;
	case PAT_SQUARE: list = list_square; break;
	case PAT_TRIANGULAR: list = list_triangular; break;
	default: list = list_checker; break;
	}
	return rgbft_of(list[i]);
}

static struct rgbft lerp(struct rgbft a, struct rgbft b, double w)
{
	struct rgbft r = {
		a.r + (b.r - a.r) * w, a.g + (b.g - a.g) * w, a.b + (b.b - a.b) * w,
		a.f + (b.f - a.f) * w, a.t + (b.t - a.t) * w,
	};
	return r;
}

static struct rgbft to_float(struct rgbft c)
{
	struct rgbft r = {(float)c.r, (float)c.g, (float)c.b, (float)c.f, (float)c.t};
	return r;
}

/* The built-in map at v, searched as blend_map_find does. */
static struct rgbft builtin_lookup(const struct builtin_map *m, double v)
{
	int n = m->n;
	if (v <= m->e[0].v)
		return rgbft_of(&m->e[0].r);
	if (v >= m->e[n - 1].v)
		return rgbft_of(&m->e[n - 1].r);
	int i = 1;
	while (i < n - 1 && m->e[i].v < v)
		i++;
	double a = m->e[i - 1].v, b = m->e[i].v;
	double w = b > a ? (v - a) / (b - a) : 1.0;
	return lerp(rgbft_of(&m->e[i - 1].r), rgbft_of(&m->e[i].r), w);
}

/* ---- pigments ---- */

static const struct rgbft TRANSPARENT = {0, 0, 0, 0, 1};

static struct rgbft entry_color(const struct blend_map *m, int i, const struct pattern_ctx *ctx)
{
	if (m->kind == MAP_COLOR)
		return m->e[i].color;
	if (!m->e[i].item)
		return TRANSPARENT;
	return pigment_eval(m->e[i].item, ctx);
}

/* Clamp a block pattern's index into the list. */
static int block_index(double v, int n)
{
	int i = (int)v;
	if (i < 0)
		i = 0;
	if (i >= n)
		i = n - 1;
	return i;
}

static struct rgbft pigment_average(const struct pigment *pg, const struct pattern_ctx *ctx)
{
	const struct blend_map *m = pg->map;
	struct rgbft sum = {0, 0, 0, 0, 0};
	double total = 0;
	if (!m)
		return sum;
	for (int i = 0; i < m->n; i++) {
		double w = m->e[i].value;
		struct rgbft c = entry_color(m, i, ctx);
		sum.r += w * c.r;
		sum.g += w * c.g;
		sum.b += w * c.b;
		sum.f += w * c.f;
		sum.t += w * c.t;
		total += w;
	}
	if (total != 0) {
		sum.r /= total;
		sum.g /= total;
		sum.b /= total;
		sum.f /= total;
		sum.t /= total;
	}
	return sum;
}

struct rgbft pigment_eval(const struct pigment *pg, const struct pattern_ctx *ctx)
{
	switch (pg->kind) {
	case PIGMENT_SOLID:
		return pg->color;
	case PIGMENT_IMAGE: {
		struct rgbft c = TRANSPARENT;
		vec3 q = pattern_point(&pg->pat, ctx->p);
		if (!pg->pat.img.img || !image_map_eval(&pg->pat.img, q, &c, NULL))
			return TRANSPARENT;
		return c;
	}
	case PIGMENT_PATTERN:
		break;
	}
	const struct pattern *pt = &pg->pat;
	if (pt->kind == PAT_AVERAGE)
		return pigment_average(pg, ctx);
	double v = pattern_value(pt, ctx);
	const struct blend_map *m = pg->map;
	if (pattern_is_block(pt->kind)) {
		int n = m ? m->n : pattern_block_entries(pt->kind);
		int i = block_index(v, n);
		return m ? entry_color(m, i, ctx) : pattern_block_default(pt->kind, i);
	}
	if (!m || m->n == 0)
		return to_float(builtin_lookup(builtin_map(pt->kind), v));
	int lo, hi;
	double w;
	blend_map_find(m, v, &lo, &hi, &w);
	struct rgbft a = entry_color(m, lo, ctx);
	if (lo == hi || w == 0.0)
		return m->kind == MAP_COLOR ? to_float(a) : a;
	struct rgbft b = entry_color(m, hi, ctx);
	struct rgbft c = lerp(a, b, w);
	return m->kind == MAP_COLOR ? to_float(c) : c;
}

/* ---- normals ---- */

/* The four directions of a regular tetrahedron: the numerical slope
 * samples the pattern at the point moved by `accuracy` along each. */
static const vec3 TETRA[4] = {
	{0.942809041582063, -0.333333333333333, 0.0},
	{-0.471404520791032, -0.333333333333333, 0.816496580927726},
	{-0.471404520791032, -0.333333333333333, -0.816496580927726},
	{0.0, 1.0, 0.0},
};

/* The height a slope_map gives at v: the cubic Hermite curve through the
 * entries' heights with their slopes. A slope counts per unit of the
 * interval's own parameter t (0 to 1), not per unit of pattern value
 * (measured in POV-Ray 3.7 with camera normals, which show the slope
 * directly: in an interval 0.5 wide the tilt is twice that of slopes per
 * unit value, and slopes 1 over [0, 0.5] and [0.5, 1] are not a line). */
static double slope_height(const struct blend_map *m, double v)
{
	int lo, hi;
	double w;
	blend_map_find(m, v, &lo, &hi, &w);
	const struct map_entry *a = &m->e[lo], *b = &m->e[hi];
	if (lo == hi)
		return a->slope[0];
	double t = w, t2 = t * t, t3 = t2 * t;
	double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t;
	double h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
	return h00 * a->slope[0] + h10 * a->slope[1] + h01 * b->slope[0] + h11 * b->slope[1];
}

double normal_height(const struct normal *nm, double v)
{
	if (nm->map && nm->map->kind == MAP_SLOPE)
		return slope_height(nm->map, v);
	return v;
}

/* The normal tilted against the numerical gradient of the height field,
 * as POV-Ray 3.7 does it (measured on a lit plane by bisecting the
 * direction of a grazing light, to 1e-4): in the pattern's space, the
 * surface normal (facing the ray) minus 2/15 of the amount times the whole
 * gradient of the height (its part along the normal too: function { x + z }
 * tilts less than function { x - z }), carried back to world space. So a
 * uniform scale leaves the tilt as it is, and scale <0.5, 1, 1> doubles
 * it across x. The gradient comes from the heights at the four
 * tetrahedral neighbours at distance `accuracy` in pattern space, after
 * the warps (pattern_value_moved; their weighted sum is 4/3
 * accuracy times it); `accuracy` changes nothing else (measured). */
#define SLOPE_BUMP (2.0 / 15.0)

static vec3 unit_or(vec3 v, vec3 fallback)
{
	double l = v3_len(v);
	return l > 0 ? v3_scale(v, 1.0 / l) : fallback;
}

static vec3 slope_normal(const struct normal *nm, vec3 n, const struct pattern_ctx *ctx)
{
	const struct pattern *pt = &nm->pat;
	double delta = nm->accuracy > 0 ? nm->accuracy : 0.02;
	vec3 g = v3(0, 0, 0);
	for (int i = 0; i < 4; i++) {
		double h = normal_height(nm, pattern_value_moved(pt, ctx->p, v3_scale(TETRA[i], delta), ctx));
		g = v3_madd(g, TETRA[i], h);
	}
	g = v3_scale(g, 3.0 / (4.0 * delta));
	vec3 np = unit_or(pattern_normal_in(pt, n), n);
	return unit_or(pattern_normal_out(pt, v3_madd(np, g, -SLOPE_BUMP * nm->amount)), n);
}

static vec3 entry_normal(const struct blend_map *m, int i, vec3 n, const struct pattern_ctx *ctx)
{
	if (!m->e[i].item)
		return n;
	return normal_eval(m->e[i].item, n, ctx);
}

vec3 normal_eval(const struct normal *nm, vec3 n, const struct pattern_ctx *ctx)
{
	const struct pattern *pt = &nm->pat;
	const struct blend_map *m = nm->map;
	if (pt->kind == PAT_NONE)
		return n;
	if (pt->kind == PAT_AVERAGE) {
		if (!m)
			return n;
		vec3 sum = v3(0, 0, 0);
		for (int i = 0; i < m->n; i++)
			sum = v3_madd(sum, entry_normal(m, i, n, ctx), m->e[i].value);
		return unit_or(sum, n);
	}
	if (m && m->kind == MAP_NORMAL) {
		double v = pattern_value(pt, ctx);
		if (pattern_is_block(pt->kind))
			return entry_normal(m, block_index(v, m->n), n, ctx);
		int lo, hi;
		double w;
		blend_map_find(m, v, &lo, &hi, &w);
		vec3 a = entry_normal(m, lo, n, ctx);
		if (lo == hi || w == 0.0)
			return a;
		vec3 b = entry_normal(m, hi, n, ctx);
		return unit_or(v3_add(v3_scale(a, 1.0 - w), v3_scale(b, w)), n);
	}
	vec3 out;
	if (pattern_special_normal(pt, nm->amount, ctx->p, n, ctx, &out))
		return out;
	return slope_normal(nm, n, ctx);
}

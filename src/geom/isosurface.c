/* isosurface.c: isosurface { function { f } [contained_by { box | sphere }]
 * [threshold T] [accuracy A] [max_gradient G] [evaluate P0, P1, P2] [open]
 * [max_trace N | all_intersections] }: the surface f(x, y, z) = T inside a
 * container; the solid is where f < T.
 *
 * The search for a crossing is POV-Ray's, measured with trace() (216 rays
 * through spheres of several sizes, centres and max_gradient values, all
 * but one tie on a dyadic point reproduced exactly; tests/unit/
 * test_isosurface.c): the ray's stretch inside the container, [a, b] with
 * values fa, fb of s (f - T) (s = 1 when the stretch starts outside the
 * solid, -1 inside), is dropped when fa + fb > G (b - a) (with gradient
 * at most G the values could not reach 0 in between), else, once
 * b - a < A, it holds a crossing if fb < 0 and the hit is b (the far end),
 * else it is halved and the nearer half searched first. Lengths are
 * distances along the ray. A ray that enters the container where f < T
 * (and the isosurface is not open) hits the container there, and one that
 * leaves it inside the solid hits it where it leaves. A ray that starts
 * inside the container begins its search 4.4 accuracies along (POV-Ray
 * misses crossings closer than 4.25 to 5 accuracies, found the same for
 * accuracies 0.001 and 0.01): the rays sent from a hit, which is up to one
 * accuracy inside, do not meet the surface they leave.
 *
 * The normal is POV-Ray's: forward differences of f with the step A,
 * (f(p + A x) - f(p), ...), pointing to where f grows; the container's own
 * normal where the container was hit.
 *
 * The greatest gradient met, |fb - fa| / (b - a) over the stretches
 * examined, is kept (atomically: render threads share the object) for
 * POV-Ray's warning after the render. With `evaluate P0, P1, P2` the
 * gradient used on each ray starts at P0 and follows what that ray meets:
 * P1 times the greatest seen so far on the ray, never below P0 (P2 damps
 * nothing here: there is no state between rays, so renders do not depend
 * on the order in which threads take rays). */
#include "geom/shapes2.h"
#include "scene/fn.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

enum { PART_SURFACE = 0, PART_CONTAINER = 1 };

struct isosurface {
	struct object base;
	struct fn *f;            /* one reference */
	bool sphere;             /* container: sphere (center, radius) or box (lo, hi) */
	vec3 lo, hi, center;
	double radius;
	double threshold, accuracy, max_gradient;
	bool evaluate;
	double eval[3];
	bool open;
	int max_trace;           /* 0: all_intersections */
	_Atomic uint64_t found;  /* the greatest gradient met, as the bits of a double */
};

static double fval(const struct isosurface *I, vec3 p)
{
	double args[3] = {p.x, p.y, p.z};
	return fn_eval(I->f, args) - I->threshold;
}

/* Record g if it is the greatest gradient met so far. */
static void note_gradient(const struct isosurface *I, double g)
{
	struct isosurface *m = (struct isosurface *)I; /* only the atomic field changes */
	uint64_t old = atomic_load_explicit(&m->found, memory_order_relaxed);
	for (;;) {
		double cur;
		memcpy(&cur, &old, sizeof cur);
		if (!(g > cur))
			return;
		uint64_t bits;
		memcpy(&bits, &g, sizeof bits);
		if (atomic_compare_exchange_weak_explicit(&m->found, &old, bits, memory_order_relaxed,
		                                          memory_order_relaxed))
			return;
	}
}

/* The ray's stretch inside the container: t0 < t1, and which ends are
 * on the container's surface (rather than the ray's own limits). */
static bool container_span(const struct isosurface *I, const struct ray *r, double *t0, double *t1)
{
	vec3 o = r->org, d = r->dir;
	if (I->sphere) {
		vec3 oc = v3_sub(o, I->center);
		double a = v3_dot(d, d), b = v3_dot(oc, d), c = v3_dot(oc, oc) - I->radius * I->radius;
		double disc = b * b - a * c;
		if (!(disc > 0) || a == 0)
			return false;
		double s = sqrt(disc);
		double q = b > 0 ? -(b + s) : -(b - s);
		double x0 = q / a, x1 = c / q;
		if (q == 0)
			x0 = x1 = -b / a;
		*t0 = fmin(x0, x1);
		*t1 = fmax(x0, x1);
		return *t0 < *t1;
	}
	double lo = -INFINITY, hi = INFINITY;
	for (int k = 0; k < 3; k++) {
		double ok = v3_get(o, k), dk = v3_get(d, k), l = v3_get(I->lo, k), h = v3_get(I->hi, k);
		if (dk == 0) {
			if (ok < l || ok > h)
				return false;
			continue;
		}
		double a = (l - ok) / dk, b = (h - ok) / dk;
		lo = fmax(lo, fmin(a, b));
		hi = fmin(hi, fmax(a, b));
	}
	*t0 = lo;
	*t1 = hi;
	return lo < hi;
}

/* The search of the file comment on [a, b] (parameters along the ray,
 * len the distance per unit of t) for the first point where s f < 0;
 * *g is the gradient in use (raised by evaluate). Returns the hit's t or
 * NAN. */
struct search {
	const struct isosurface *I;
	vec3 o, d;
	double len, s, g, gmax;
};

static double find(struct search *S, double a, double b, double fa, double fb, int depth)
{
	double dist = (b - a) * S->len;
	if (dist > 0) {
		double grad = fabs(fb - fa) / dist;
		if (grad > S->gmax) {
			S->gmax = grad;
			if (S->I->evaluate)
				S->g = fmax(S->I->eval[0], S->I->eval[1] * grad);
		}
	}
	if (S->s * fa + S->s * fb > S->g * dist)
		return NAN;
	if (dist < S->I->accuracy || depth > 60)
		return S->s * fb < 0 ? b : NAN;
	double m = 0.5 * (a + b), fm = fval(S->I, v3_madd(S->o, S->d, m));
	double t = find(S, a, m, fa, fm, depth + 1);
	if (!isnan(t))
		return t;
	return find(S, m, b, fm, fb, depth + 1);
}

typedef bool (*hit_sink)(void *ctx, double t, int part);

/* Every crossing with tmin < t < tmax in increasing t, up to the
 * isosurface's max_trace, passed to take (which may stop the walk). */
static void iso_hits(const struct isosurface *I, const struct ray *r, double tmin, double tmax, int limit,
                     hit_sink take, void *ctx)
{
	double t0, t1;
	if (!container_span(I, r, &t0, &t1))
		return;
	bool enters = t0 > tmin, leaves = t1 < tmax;
	double a = fmax(t0, tmin), b = fmin(t1, tmax);
	if (!(a < b))
		return;
	struct search S = {.I = I, .o = r->org, .d = r->dir, .len = v3_len(r->dir), .gmax = 0};
	S.g = I->evaluate ? I->eval[0] : I->max_gradient;
	if (!enters) {
		/* A ray that starts in the container skips its first 4.4
		 * accuracies (see the file comment). */
		a += 4.4 * I->accuracy / S.len;
		if (!(a < b))
			return;
	}
	double fa = fval(I, v3_madd(S.o, S.d, a));
	int count = 0;
	if (fa < 0) {
		if (enters && !I->open) {
			if (!take(ctx, a, PART_CONTAINER))
				goto done;
			if (limit && ++count >= limit)
				goto done;
		}
		S.s = -1;
	} else {
		S.s = 1;
	}
	for (;;) {
		double fb = fval(I, v3_madd(S.o, S.d, b));
		double t = find(&S, a, b, fa, fb, 0);
		if (isnan(t))
			break;
		if (!take(ctx, t, PART_SURFACE))
			goto done;
		if (limit && ++count >= limit)
			goto done;
		a = t;
		fa = fval(I, v3_madd(S.o, S.d, a));
		S.s = -S.s;
	}
	/* Leaving the container inside the solid. */
	if (leaves && !I->open && S.s < 0) {
		double fb = fval(I, v3_madd(S.o, S.d, t1));
		if (fb < 0)
			take(ctx, t1, PART_CONTAINER);
	}
done:
	note_gradient(I, S.gmax);
}

struct closest {
	double t;
	int part;
	bool found;
};

static bool take_first(void *ctx, double t, int part)
{
	struct closest *c = ctx;
	c->t = t;
	c->part = part;
	c->found = true;
	return false;
}

static bool iso_intersect(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *h)
{
	struct closest c = {.found = false};
	iso_hits((const struct isosurface *)o, r, tmin, tmax, 1, take_first, &c);
	if (!c.found)
		return false;
	h->t = c.t;
	h->part = c.part;
	return true;
}

struct all {
	const struct object *o;
	struct hit *out;
	int n, max;
};

static bool take_all(void *ctx, double t, int part)
{
	struct all *a = ctx;
	if (a->n >= a->max)
		return false;
	a->out[a->n++] = (struct hit){.t = t, .obj = a->o, .part = part};
	return true;
}

static int iso_all_hits(const struct object *o, const struct ray *r, double tmin, double tmax, struct hit *out,
                        int max)
{
	const struct isosurface *I = (const struct isosurface *)o;
	struct all a = {.o = o, .out = out, .max = max};
	if (max > 0)
		iso_hits(I, r, tmin, tmax, I->max_trace, take_all, &a);
	return a.n;
}

static bool in_container(const struct isosurface *I, vec3 p)
{
	if (I->sphere) {
		vec3 q = v3_sub(p, I->center);
		return v3_dot(q, q) <= I->radius * I->radius;
	}
	return p.x >= I->lo.x && p.x <= I->hi.x && p.y >= I->lo.y && p.y <= I->hi.y && p.z >= I->lo.z &&
	       p.z <= I->hi.z;
}

static bool iso_inside(const struct object *o, vec3 p)
{
	const struct isosurface *I = (const struct isosurface *)o;
	return in_container(I, p) && fval(I, p) < 0;
}

static vec3 container_normal(const struct isosurface *I, vec3 p)
{
	if (I->sphere)
		return v3_sub(p, I->center);
	/* The face the point is nearest to. */
	double best = INFINITY;
	vec3 n = v3(0, 1, 0);
	for (int k = 0; k < 3; k++) {
		double pk = v3_get(p, k), dl = fabs(pk - v3_get(I->lo, k)), dh = fabs(pk - v3_get(I->hi, k));
		if (dl < best) {
			best = dl;
			n = v3(k == 0 ? -1 : 0, k == 1 ? -1 : 0, k == 2 ? -1 : 0);
		}
		if (dh < best) {
			best = dh;
			n = v3(k == 0, k == 1, k == 2);
		}
	}
	return n;
}

static vec3 iso_normal(const struct object *o, vec3 p, const struct hit *h)
{
	const struct isosurface *I = (const struct isosurface *)o;
	if (h->part == PART_CONTAINER)
		return container_normal(I, p);
	double e = I->accuracy, f0 = fval(I, p);
	vec3 n = v3(fval(I, v3(p.x + e, p.y, p.z)) - f0, fval(I, v3(p.x, p.y + e, p.z)) - f0,
	            fval(I, v3(p.x, p.y, p.z + e)) - f0);
	if (!(v3_dot(n, n) > 0) || !isfinite(v3_dot(n, n)))
		return v3(0, 1, 0);
	return n;
}

static struct aabb iso_bounds(const struct object *o)
{
	const struct isosurface *I = (const struct isosurface *)o;
	if (I->sphere) {
		vec3 r = v3(I->radius, I->radius, I->radius);
		return (struct aabb){v3_sub(I->center, r), v3_add(I->center, r)};
	}
	return (struct aabb){I->lo, I->hi};
}

static struct object *iso_copy(const struct object *o)
{
	const struct isosurface *I = (const struct isosurface *)o;
	struct isosurface *c = malloc(sizeof *c);
	if (!c) abort();
	memcpy(c, I, sizeof *c);
	atomic_init(&c->found, atomic_load(&((struct isosurface *)I)->found));
	c->f = fn_ref(I->f);
	return &c->base;
}

static void iso_destroy(struct object *o)
{
	fn_unref(((struct isosurface *)o)->f);
}

static const struct object_ops iso_ops = {
	.name = "isosurface",
	.intersect = iso_intersect,
	.all_hits = iso_all_hits,
	.inside = iso_inside,
	.normal = iso_normal,
	.bounds = iso_bounds,
	.copy = iso_copy,
	.destroy = iso_destroy,
};

struct object *isosurface_new(struct fn *f, struct srcpos pos)
{
	struct isosurface *I = calloc(1, sizeof *I);
	if (!I) abort();
	object_init(&I->base, &iso_ops, pos);
	I->f = fn_ref(f);
	I->lo = v3(-1, -1, -1);
	I->hi = v3(1, 1, 1);
	I->accuracy = 0.001;
	I->max_gradient = 1.1;
	I->max_trace = 1;
	atomic_init(&I->found, 0);
	return &I->base;
}

static struct isosurface *iso(struct object *o)
{
	return (struct isosurface *)o;
}

void isosurface_set_box(struct object *o, vec3 c1, vec3 c2)
{
	iso(o)->sphere = false;
	iso(o)->lo = v3_min(c1, c2);
	iso(o)->hi = v3_max(c1, c2);
}

void isosurface_set_sphere(struct object *o, vec3 center, double radius)
{
	iso(o)->sphere = true;
	iso(o)->center = center;
	iso(o)->radius = fabs(radius);
}

void isosurface_set_threshold(struct object *o, double threshold) { iso(o)->threshold = threshold; }
void isosurface_set_accuracy(struct object *o, double accuracy) { iso(o)->accuracy = accuracy; }
void isosurface_set_max_gradient(struct object *o, double max_gradient) { iso(o)->max_gradient = max_gradient; }
void isosurface_set_open(struct object *o, bool open) { iso(o)->open = open; }
void isosurface_set_max_trace(struct object *o, int n) { iso(o)->max_trace = n; }

void isosurface_set_evaluate(struct object *o, double p0, double p1, double p2)
{
	iso(o)->evaluate = true;
	iso(o)->eval[0] = p0;
	iso(o)->eval[1] = p1;
	iso(o)->eval[2] = p2;
}

bool isosurface_gradient_report(const struct object *o, double *found, double *given)
{
	if (o->ops != &iso_ops)
		return false;
	const struct isosurface *I = (const struct isosurface *)o;
	uint64_t bits = atomic_load(&((struct isosurface *)I)->found);
	memcpy(found, &bits, sizeof *found);
	*given = I->evaluate ? I->eval[0] : I->max_gradient;
	return true;
}

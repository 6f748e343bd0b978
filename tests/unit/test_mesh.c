/* test_mesh.c: unit tests for triangles, smooth triangles and meshes
 * (src/geom/triangle.c, src/geom/mesh.c, src/geom/tri.c): hits, misses,
 * normals and degenerate input of the single triangles; meshes against
 * brute force over their own triangles (same t to the bit); watertightness
 * of closed meshes for rays aimed exactly at edges and vertices, from
 * outside and inside; inside_vector; shared data on copy; uv vectors,
 * textures and smooth normals; and the build time of a 1M-triangle mesh
 * (printed, not asserted). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/mesh.h"
#include "geom/shapes.h"
#include "geom/tri.h"
#include "math/hash.h"
#include "scene/object.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "testutil.h"

static const struct srcpos nopos = {0, 0, 0};

static struct ray mkray(vec3 org, vec3 dir)
{
	struct ray r = {org, dir};
	return r;
}

static bool hits(const struct object *o, vec3 org, vec3 dir, double tmin, double tmax, struct hit *h)
{
	struct ray r = mkray(org, dir);
	struct hit tmp;
	return object_intersect(o, &r, tmin, tmax, h ? h : &tmp);
}

static struct hit must_hit(const struct object *o, vec3 org, vec3 dir, double tmin)
{
	struct hit h = {.t = -1, .part = -1};
	if (!hits(o, org, dir, tmin, INFINITY, &h))
		fail_msg("ray <%.17g,%.17g,%.17g> + t<%.17g,%.17g,%.17g> missed the %s", org.x, org.y, org.z,
		         dir.x, dir.y, dir.z, o->ops->name);
	assert_ptr_equal(h.obj, o);
	return h;
}

static int count_hits(const struct object *o, vec3 org, vec3 dir, double tmin)
{
	struct ray r = mkray(org, dir);
	struct hit out[64];
	return o->ops->all_hits(o, &r, tmin, INFINITY, out, 64);
}

static double urand(uint32_t i, uint32_t purpose) { return hash_uniform(i, 7, 0, purpose); }

static vec3 rand_unit(uint32_t i, uint32_t purpose)
{
	double z = 2 * urand(i, purpose) - 1, phi = 2 * M_PI * urand(i, purpose + 1);
	double s = sqrt(1 - z * z);
	return v3(s * cos(phi), s * sin(phi), z);
}

/* ---- the triangle test itself ---- */

static void test_tri_basic(void **state)
{
	(void)state;
	vec3 a = v3(0, 0, 0), b = v3(1, 0, 0), c = v3(0, 1, 0);
	struct tri_ray tr;
	struct tri_hit th;
	struct ray r = mkray(v3(0.25, 0.5, -2), v3(0, 0, 1));
	assert_true(tri_ray_init(&tr, &r));
	assert_true(tri_intersect(&tr, a, b, c, 0, INFINITY, &th));
	assert_near(th.t, 2, 0);
	assert_near(th.u, 0.25, 0); /* weight of b */
	assert_near(th.v, 0.5, 0);  /* weight of c */
	/* Both faces; tmin and tmax exclusive. */
	r = mkray(v3(0.25, 0.5, 3), v3(0, 0, -1));
	assert_true(tri_ray_init(&tr, &r));
	assert_true(tri_intersect(&tr, a, b, c, 0, INFINITY, &th));
	assert_near(th.t, 3, 0);
	assert_false(tri_intersect(&tr, a, b, c, 3, INFINITY, &th));
	assert_false(tri_intersect(&tr, a, b, c, 0, 3, &th));
	/* A zero or non-finite direction prepares nothing. */
	r = mkray(v3(0, 0, 0), v3(0, 0, 0));
	assert_false(tri_ray_init(&tr, &r));
	r = mkray(v3(0, 0, 0), v3(NAN, 0, 1));
	assert_false(tri_ray_init(&tr, &r));
	/* Edge functions whose products round to equal doubles: a sliver whose
	 * exact edge values are 14e, e/2 - e^2/2 and 36e - 64e^2 (e = 2^-52),
	 * all positive, while the plain double differences give 0, 0, 64e. */
	const double e = 0x1p-52;
	r = mkray(v3(0, 0, -1), v3(0, 0, 1));
	assert_true(tri_ray_init(&tr, &r));
	vec3 sa = v3(1 + e, 1, 0), sb = v3(-100, -100 + 64 * e, 0), sc = v3(1, 1 - e / 2, 0);
	assert_true((1 + e) * (1 - e / 2) == 1); /* the rounding the test relies on */
	assert_true(tri_intersect(&tr, sa, sb, sc, 0, INFINITY, &th));
	assert_near(th.t, 1, 0);
	assert_true(tri_intersect(&tr, sa, sc, sb, 0, INFINITY, &th)); /* either winding */
	/* Degenerate triangles. */
	assert_true(tri_degenerate(a, b, v3(2, 0, 0)));
	assert_true(tri_degenerate(a, a, c));
	assert_true(tri_degenerate(a, b, v3(INFINITY, 0, 0)));
	assert_false(tri_degenerate(a, b, c));
	assert_false(tri_degenerate(a, v3(1e-200, 0, 0), v3(0, 1e-100, 0)));
}

/* Two triangles sharing an edge, rays exactly through the edge and the
 * shared corners: exactly one of the two takes each ray. */
static void test_tri_shared_edge_exactly_once(void **state)
{
	(void)state;
	vec3 a = v3(0, 0, 0), b = v3(1, 0, 0), c = v3(0, 1, 0), d = v3(1, 1, 0);
	/* abc and the neighbour across bc, wound both ways. */
	vec3 t2[2][3] = {{c, b, d}, {b, c, d}};
	vec3 targets[] = {v3(0.5, 0.5, 0), v3(0.25, 0.75, 0), b, c};
	vec3 dirs[] = {v3(0, 0, 1), v3(0, 0, -1), v3(0.5, 0.25, 1), v3(-0.5, 0.25, 1), v3(0.5, -0.5, 1),
	               v3(-0.25, -0.5, -1), v3(1, 1, 1), v3(1, 1, -1), v3(-1, -1, 0.5)};
	for (int w = 0; w < 2; w++)
		for (size_t i = 0; i < sizeof targets / sizeof targets[0]; i++)
			for (size_t k = 0; k < sizeof dirs / sizeof dirs[0]; k++) {
				/* Origins 4 direction lengths back: exact in binary. */
				struct ray r = mkray(v3_madd(targets[i], dirs[k], -4), dirs[k]);
				struct tri_ray tr;
				struct tri_hit h1, h2;
				assert_true(tri_ray_init(&tr, &r));
				bool x = tri_intersect(&tr, a, b, c, 0, INFINITY, &h1);
				bool y = tri_intersect(&tr, t2[w][0], t2[w][1], t2[w][2], 0, INFINITY, &h2);
				if (i < 2 && x + y != 1)
					fail_msg("edge point %zu dir %zu winding %d: %d + %d hits", i, k, w, x, y);
				if (i >= 2 && x + y > 1)
					fail_msg("corner %zu dir %zu winding %d: two hits", i, k, w);
				if (x) assert_near(h1.t, 4, 1e-15);
				if (y) assert_near(h2.t, 4, 1e-15);
			}
}

/* ---- triangle and smooth_triangle objects ---- */

static void test_triangle_hit_miss(void **state)
{
	(void)state;
	struct object *t = triangle_new(v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 0), nopos);
	vec3 dz = v3(0, 0, 1);
	struct hit h = must_hit(t, v3(0.5, 0.5, -3), dz, 0);
	assert_near(h.t, 3, 0);
	assert_int_equal(h.part, 0);
	assert_near(h.u, 0.25, 0);
	assert_near(h.v, 0.25, 0);
	/* The flat normal (c-a)x(b-a), POV-Ray's orientation (its trace()
	 * gives -z for this triangle), whichever side the ray comes from. */
	assert_vec_near(object_normal(t, v3(0.5, 0.5, 0), &h), 0, 0, -1, 0);
	h = must_hit(t, v3(0.5, 0.5, 3), v3(0, 0, -2), 0);
	assert_near(h.t, 1.5, 0);
	/* Misses: outside the hypotenuse, behind, beyond tmax, parallel. */
	assert_false(hits(t, v3(1.01, 1.01, -3), dz, 0, INFINITY, NULL));
	assert_false(hits(t, v3(-0.01, 0.5, -3), dz, 0, INFINITY, NULL));
	assert_false(hits(t, v3(0.5, 0.5, 1), dz, 0, INFINITY, NULL));
	assert_false(hits(t, v3(0.5, 0.5, -3), dz, 0, 3, NULL));
	assert_true(hits(t, v3(0.5, 0.5, -3), dz, 0, 3.0000001, NULL));
	assert_false(hits(t, v3(-1, 0.5, 1), v3(1, 0, 0), 0, INFINITY, NULL));
	/* A ray lying in the plane of the triangle never hits. */
	assert_false(hits(t, v3(-1, 0.5, 0), v3(1, 0, 0), 0, INFINITY, NULL));
	assert_false(hits(t, v3(-1, -1, 0), v3(1, 1, 0), 0, INFINITY, NULL));
	/* A ray starting on the surface: t = 0 is excluded. */
	assert_false(hits(t, v3(0.5, 0.5, 0), dz, 0, INFINITY, NULL));
	assert_false(hits(t, v3(0.5, 0.5, 0), v3(0, 0, 0), 0, INFINITY, NULL));
	/* Oblique: from <3,3,-3> toward <0.5,0.25,0>. */
	vec3 org = v3(3, 3, -3), dir = v3_sub(v3(0.5, 0.25, 0), org);
	h = must_hit(t, org, dir, 0);
	assert_near(h.t, 1, 1e-15);
	assert_near(h.u, 0.25, 1e-15);
	assert_near(h.v, 0.125, 1e-15);
	/* No inside; bounds are the corners', widened by 1e-10 (POV-Ray's). */
	assert_false(object_inside(t, v3(0.5, 0.5, 0)));
	assert_false(object_inside(t, v3(0.5, 0.5, -1e-9)));
	struct aabb b = t->ops->bounds(t);
	assert_vec_near(b.lo, -1e-10, -1e-10, -1e-10, 0);
	assert_vec_near(b.hi, 2 + 1e-10, 2 + 1e-10, 1e-10, 0);
	assert_null(t->ops->uv);
	struct hit all[4];
	struct ray r = mkray(v3(0.5, 0.5, -3), dz);
	assert_int_equal(t->ops->all_hits(t, &r, 0, INFINITY, all, 4), 1);
	assert_ptr_equal(all[0].obj, t);
	assert_near(all[0].t, 3, 0);
	object_free(t);
}

static void test_triangle_transformed(void **state)
{
	(void)state;
	struct object *t = triangle_new(v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), nopos);
	struct xform s = xform_scale(v3(2, 4, 1)), tr = xform_translate(v3(0, 0, 5));
	object_transform(t, &s);
	object_transform(t, &tr);
	/* World triangle (0,0,5) (2,0,5) (0,4,5). */
	struct hit h = must_hit(t, v3(0.5, 1, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 5, 1e-15);
	assert_near(h.u, 0.25, 1e-15);
	assert_near(h.v, 0.25, 1e-15);
	assert_vec_near(object_normal(t, v3(0.5, 1, 5), &h), 0, 0, -1, 1e-15);
	assert_false(hits(t, v3(1.5, 1.5, 0), v3(0, 0, 1), 0, INFINITY, NULL));
	struct aabb b = object_world_bounds(t);
	assert_vec_near(b.lo, -1e-10, -1e-10, 5 - 1e-10, 1e-15);
	assert_vec_near(b.hi, 2 + 1e-10, 4 + 1e-10, 5 + 1e-10, 1e-15);
	struct object *c = object_copy(t);
	h = must_hit(c, v3(0.5, 1, 0), v3(0, 0, 1), 0);
	assert_near(h.t, 5, 1e-15);
	object_free(t);
	object_free(c);
}

static void test_triangle_degenerate(void **state)
{
	(void)state;
	/* Collinear, coincident and zero-size triangles are never hit. */
	struct object *t[3] = {
	    triangle_new(v3(0, 0, 0), v3(1, 1, 0), v3(2, 2, 0), nopos),
	    triangle_new(v3(0, 0, 0), v3(0, 0, 0), v3(1, 0, 0), nopos),
	    triangle_new(v3(1, 1, 1), v3(1, 1, 1), v3(1, 1, 1), nopos),
	};
	for (int i = 0; i < 3; i++) {
		assert_false(hits(t[i], v3(1, 1, -1), v3(0, 0, 1), 0, INFINITY, NULL));
		assert_false(hits(t[i], v3(0.5, 0.5, -1), v3(0, 0, 1), 0, INFINITY, NULL));
		assert_false(hits(t[i], v3(1, 1, -1), v3(0, 0, 1), -INFINITY, INFINITY, NULL));
		assert_false(hits(t[i], v3(0, 0, -1), v3(0.5, 0, 1), 0, INFINITY, NULL));
		object_free(t[i]);
	}
}

static void test_smooth_triangle(void **state)
{
	(void)state;
	/* POV-Ray normalises the vertex normals and interpolates them linearly
	 * (checked by rendering): the lengths do not matter. */
	vec3 a = v3(-2, -2, 0), b = v3(2, -2, 0), c = v3(0, 2, 0);
	struct object *t = smooth_triangle_new(a, v3(10, 0, -10), b, v3(-1, 0, -1), c, v3(0, 0, -1), nopos);
	assert_string_equal(t->ops->name, "smooth_triangle");
	/* Halfway along ab the two tilts cancel. */
	struct hit h = must_hit(t, v3(0, -2 + 1e-9, -5), v3(0, 0, 1), 0);
	assert_vec_near(object_normal(t, v3(0, -2, 0), &h), 0, 0, -1, 1e-8);
	/* At a corner, that corner's normal. */
	h = must_hit(t, v3(-2 + 1e-9, -2 + 2e-9, -5), v3(0, 0, 1), 0);
	assert_vec_near(object_normal(t, a, &h), M_SQRT1_2, 0, -M_SQRT1_2, 1e-8);
	/* In the middle: the weights (1-u-v, u, v) applied to the unit normals. */
	vec3 org = v3(0.5, -1, -5);
	h = must_hit(t, org, v3(0, 0, 1), 0);
	double wa = 1 - h.u - h.v;
	vec3 ex = v3_norm(v3(M_SQRT1_2 * wa - M_SQRT1_2 * h.u, 0, -M_SQRT1_2 * wa - M_SQRT1_2 * h.u - h.v));
	vec3 n = object_normal(t, v3(0.5, -1, 0), &h);
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-15);
	assert_near(h.u, 0.5, 1e-15); /* (0.5,-1): weights 0.25, 0.5, 0.25 */
	assert_near(h.v, 0.25, 1e-15);
	/* Without a hit record the barycentrics come from the point. */
	n = object_normal(t, v3(0.5, -1, 0), NULL);
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-15);
	/* Same geometry as a flat triangle with the same t. */
	struct object *f = triangle_new(a, b, c, nopos);
	struct hit hf = must_hit(f, org, v3(0, 0, 1), 0);
	assert_near(hf.t, h.t, 0);
	assert_false(object_inside(t, v3(0, 0, 0)));
	object_free(f);
	object_free(t);

	/* Normals on both sides of the plane (or in it, or zero): POV-Ray
	 * drops the stand-alone smooth triangle as degenerate. */
	vec3 bad[][3] = {
	    {{0, 0, 1}, {0, 0, -1}, {0, 0, -1}},
	    {{1, 0, 0}, {0, 0, -1}, {0, 0, -1}},
	    {{1, 0, 0.5}, {-1, 0, 0.5}, {0, 0, -1}},
	    {{0, 0, 0}, {0, 0, -1}, {0, 0, -1}},
	};
	for (int i = 0; i < 4; i++) {
		t = smooth_triangle_new(a, bad[i][0], b, bad[i][1], c, bad[i][2], nopos);
		assert_false(hits(t, v3(0, 0, -5), v3(0, 0, 1), 0, INFINITY, NULL));
		object_free(t);
	}
	/* All on the far side is fine. */
	t = smooth_triangle_new(a, v3(0, 0, 1), b, v3(1, 0, 0.01), c, v3(0, 0, 1), nopos);
	h = must_hit(t, v3(0, 0, -5), v3(0, 0, 1), 0);
	assert_near(h.t, 5, 0);
	object_free(t);
}

/* ---- meshes: construction helpers ---- */

/* A mesh2 from arrays. */
static struct object *mesh_from(const vec3 *v, size_t nv, const uint32_t (*f)[3], size_t nf, vec3 inside)
{
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH2);
	for (size_t i = 0; i < nv; i++)
		assert_int_equal(mesh_add_vertex(b, v[i]), i);
	for (size_t i = 0; i < nf; i++)
		assert_true(mesh_add_face(b, f[i], 0, NULL));
	mesh_set_inside_vector(b, inside);
	return mesh_new(b, nopos);
}

/* An icosphere of radius 1: the icosahedron subdivided `levels` times,
 * vertices on the sphere rounded to multiples of 2^-20 so that edge
 * midpoints and rays through them are exact in binary. */
struct icosphere {
	vec3 *v;
	uint32_t (*f)[3];
	size_t nv, nf;
};

static vec3 quantize(vec3 p)
{
	const double q = 1048576.0;
	return v3(nearbyint(p.x * q) / q, nearbyint(p.y * q) / q, nearbyint(p.z * q) / q);
}

static uint32_t ico_vertex(struct icosphere *s, vec3 p)
{
	for (size_t i = 0; i < s->nv; i++)
		if (s->v[i].x == p.x && s->v[i].y == p.y && s->v[i].z == p.z)
			return (uint32_t)i;
	s->v[s->nv] = p;
	return (uint32_t)s->nv++;
}

static struct icosphere icosphere(int levels)
{
	size_t maxf = 20, maxv = 12;
	for (int l = 0; l < levels; l++) {
		maxv += maxf * 3 / 2;
		maxf *= 4;
	}
	struct icosphere s = {malloc(maxv * sizeof *s.v), malloc(maxf * sizeof *s.f), 0, 0};
	const double p = (1 + sqrt(5)) / 2;
	vec3 base[12] = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
	                 {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
	static const uint32_t faces[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
	                                      {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
	                                      {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
	                                      {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
	for (int i = 0; i < 12; i++)
		s.v[s.nv++] = quantize(v3_norm(base[i]));
	memcpy(s.f, faces, sizeof faces);
	s.nf = 20;
	for (int l = 0; l < levels; l++) {
		uint32_t (*nf)[3] = malloc(s.nf * 4 * sizeof *nf);
		size_t n = 0;
		for (size_t i = 0; i < s.nf; i++) {
			uint32_t a = s.f[i][0], b = s.f[i][1], c = s.f[i][2];
			uint32_t ab = ico_vertex(&s, quantize(v3_norm(v3_add(s.v[a], s.v[b]))));
			uint32_t bc = ico_vertex(&s, quantize(v3_norm(v3_add(s.v[b], s.v[c]))));
			uint32_t ca = ico_vertex(&s, quantize(v3_norm(v3_add(s.v[c], s.v[a]))));
			uint32_t q[4][3] = {{a, ab, ca}, {ab, b, bc}, {ca, bc, c}, {ab, bc, ca}};
			memcpy(nf[n], q, sizeof q);
			n += 4;
		}
		memcpy(s.f, nf, n * sizeof *nf);
		s.nf = n;
		free(nf);
	}
	return s;
}

static vec3 face_normal(const vec3 *v, const uint32_t f[3])
{
	return v3_cross(v3_sub(v[f[1]], v[f[0]]), v3_sub(v[f[2]], v[f[0]]));
}

/* The brute-force closest hit over the mesh's own triangles. */
static bool brute_closest(const struct object *m, const struct ray *r, double tmin, double tmax, struct tri_hit *best,
                          size_t *part)
{
	struct mesh_stats st;
	mesh_get_stats(m, &st);
	struct tri_ray tr;
	if (!tri_ray_init(&tr, r))
		return false;
	bool found = false;
	for (size_t i = 0; i < st.triangles; i++) {
		vec3 c[3];
		struct tri_hit th;
		mesh_triangle(m, i, c);
		if (tri_intersect(&tr, c[0], c[1], c[2], tmin, tmax, &th)) {
			*best = th;
			*part = i;
			tmax = th.t;
			found = true;
		}
	}
	return found;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

/* ---- meshes ---- */

static void test_mesh_matches_brute_force(void **state)
{
	(void)state;
	/* An icosphere plus a soup of random triangles in and around it. */
	struct icosphere s = icosphere(3);
	size_t nsoup = 3000, nv = s.nv + 3 * nsoup, nf = s.nf + nsoup;
	vec3 *v = malloc(nv * sizeof *v);
	uint32_t (*f)[3] = malloc(nf * sizeof *f);
	memcpy(v, s.v, s.nv * sizeof *v);
	memcpy(f, s.f, s.nf * sizeof *f);
	for (size_t i = 0; i < nsoup; i++) {
		vec3 c = v3(4 * urand(i, 1) - 2, 4 * urand(i, 2) - 2, 4 * urand(i, 3) - 2);
		double size = 0.02 + 0.3 * urand(i, 4);
		for (int k = 0; k < 3; k++) {
			v[s.nv + 3 * i + k] = v3_madd(c, rand_unit(3 * (uint32_t)i + k, 10), size);
			f[s.nf + i][k] = (uint32_t)(s.nv + 3 * i + k);
		}
	}
	struct object *m = mesh_from(v, nv, f, nf, v3(0, 0, 0));
	struct mesh_stats st;
	mesh_get_stats(m, &st);
	assert_int_equal(st.triangles, nf);
	assert_int_equal(st.vertices, nv);
	assert_true(st.nodes > 1 && st.nodes < 2 * nf);
	int nhit = 0;
	for (uint32_t i = 0; i < 20000; i++) {
		vec3 org = v3(6 * urand(i, 20) - 3, 6 * urand(i, 21) - 3, 6 * urand(i, 22) - 3);
		vec3 dir = v3_scale(rand_unit(i, 23), 0.1 + 3 * urand(i, 25));
		if (i % 4 == 0) /* axis-parallel directions */
			dir = v3_scale((vec3[]){{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}[i / 4 % 3], 0.5 + urand(i, 26));
		double tmin = i % 3 == 0 ? 0.3 * urand(i, 27) : 0, tmax = i % 5 == 0 ? 2 * urand(i, 28) : INFINITY;
		struct ray r = mkray(org, dir);
		struct hit h;
		struct tri_hit bh;
		size_t bp = 0;
		bool a = m->ops->intersect(m, &r, tmin, tmax, &h);
		bool b = brute_closest(m, &r, tmin, tmax, &bh, &bp);
		if (a != b)
			fail_msg("ray %u: mesh %d, brute force %d", i, a, b);
		if (!a)
			continue;
		nhit++;
		if (h.t != bh.t)
			fail_msg("ray %u: mesh t %.17g, brute force %.17g", i, h.t, bh.t);
		if ((size_t)h.part == bp) {
			assert_true(h.u == bh.u && h.v == bh.v);
		} else { /* a tie: the other triangle gives the same t */
			vec3 c[3];
			struct tri_ray tr;
			struct tri_hit th;
			mesh_triangle(m, (size_t)h.part, c);
			assert_true(tri_ray_init(&tr, &r));
			assert_true(tri_intersect(&tr, c[0], c[1], c[2], tmin, INFINITY, &th));
			assert_true(th.t == h.t);
		}
		/* all_hits: every crossing, sorted, equal to brute force. */
		struct hit out[256];
		int n = m->ops->all_hits(m, &r, tmin, tmax, out, 256);
		double ts[256];
		int nb = 0;
		struct tri_ray tr;
		assert_true(tri_ray_init(&tr, &r));
		for (size_t k = 0; k < st.triangles; k++) {
			vec3 c[3];
			struct tri_hit th;
			mesh_triangle(m, k, c);
			if (tri_intersect(&tr, c[0], c[1], c[2], tmin, tmax, &th) && nb < 256)
				ts[nb++] = th.t;
		}
		qsort(ts, (size_t)nb, sizeof ts[0], cmp_double);
		assert_int_equal(n, nb);
		for (int k = 0; k < n; k++) {
			assert_true(out[k].t == ts[k]);
			assert_ptr_equal(out[k].obj, m);
		}
		/* With room for fewer, the nearest ones in order. */
		if (n >= 3) {
			struct hit few[2];
			assert_int_equal(m->ops->all_hits(m, &r, tmin, tmax, few, 2), 2);
			assert_true(few[0].t == ts[0] && few[1].t == ts[1]);
		}
	}
	print_message("%d of 20000 random rays hit\n", nhit);
	assert_true(nhit > 4000);
	object_free(m);
	free(v);
	free(f);
	free(s.v);
	free(s.f);
}

/* Per ray through an exact target point: hit it, with exactly `expect`
 * crossings in all (a convex closed mesh: 2 from outside, 1 from inside). */
static void check_crossings(const struct object *m, vec3 org, vec3 target, int expect, const char *what)
{
	vec3 dir = v3_sub(target, org); /* exact: all coordinates are multiples of 2^-20 below 2^5 */
	assert_true(v3_add(org, dir).x == target.x && v3_add(org, dir).y == target.y && v3_add(org, dir).z == target.z);
	struct hit h;
	if (!hits(m, org, dir, 0, INFINITY, &h))
		fail_msg("%s: ray <%.17g,%.17g,%.17g> + t<%.17g,%.17g,%.17g> passed through", what, org.x, org.y,
		         org.z, dir.x, dir.y, dir.z);
	if (expect == 2 && fabs(h.t - 1) > 1e-9)
		fail_msg("%s: first hit at t = %.17g, expected 1", what, h.t);
	int n = count_hits(m, org, dir, 0);
	if (n != expect)
		fail_msg("%s: %d crossings, expected %d (ray <%.17g,%.17g,%.17g> + t<%.17g,%.17g,%.17g>)", what, n,
		         expect, org.x, org.y, org.z, dir.x, dir.y, dir.z);
}

/* Does the ray direction d meet every face in list strictly from outside
 * (|cos| > 0.1)? Otherwise it grazes the surface there, and may rightly
 * touch it without entering. */
static bool enters_all(const struct icosphere *s, const uint32_t *faces, int n, vec3 d)
{
	vec3 dn = v3_norm(d);
	for (int i = 0; i < n; i++) {
		vec3 fn = v3_norm(face_normal(s->v, s->f[faces[i]]));
		vec3 c = s->v[s->f[faces[i]][0]];
		if (v3_dot(fn, c) < 0) fn = v3_neg(fn); /* outward */
		if (!(v3_dot(dn, fn) < -0.1))
			return false;
	}
	return true;
}

static void test_mesh_watertight_icosphere(void **state)
{
	(void)state;
	struct icosphere s = icosphere(4);
	assert_int_equal(s.nf, 5120);
	assert_int_equal(s.nv, 2562);
	/* Flip the winding of every third face: the test must not care. */
	for (size_t i = 0; i < s.nf; i += 3) {
		uint32_t t = s.f[i][1];
		s.f[i][1] = s.f[i][2];
		s.f[i][2] = t;
	}
	struct object *m = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(0, 0, 0));

	/* Faces around each vertex, and the two faces of each edge. */
	int *nfan = calloc(s.nv, sizeof *nfan);
	uint32_t (*fan)[6] = malloc(s.nv * sizeof *fan);
	for (size_t i = 0; i < s.nf; i++)
		for (int k = 0; k < 3; k++) {
			uint32_t v = s.f[i][k];
			assert_true(nfan[v] < 6);
			fan[v][nfan[v]++] = (uint32_t)i;
		}
	long rays = 0;
	for (size_t vi = 0; vi < s.nv; vi++) {
		vec3 p = s.v[vi];
		/* From outside, through the vertex, from many directions. */
		for (uint32_t k = 0; k < 12; k++) {
			vec3 org = quantize(v3_madd(p, rand_unit((uint32_t)vi * 12 + k, 40), 3));
			if (!enters_all(&s, fan[vi], nfan[vi], v3_sub(p, org)))
				continue;
			check_crossings(m, org, p, 2, "vertex from outside");
			rays++;
		}
		/* From the centre and from off-centre inside points. */
		check_crossings(m, v3(0, 0, 0), p, 1, "vertex from the centre");
		check_crossings(m, quantize(v3(0.1, -0.2, 0.3)), p, 1, "vertex from inside");
		rays += 2;
	}
	for (size_t fi = 0; fi < s.nf; fi++)
		for (int e = 0; e < 3; e++) {
			uint32_t a = s.f[fi][e], b = s.f[fi][(e + 1) % 3];
			if (a > b)
				continue; /* each edge once */
			/* The other face on this edge. */
			uint32_t pair[2] = {(uint32_t)fi, 0};
			for (int k = 0; k < nfan[a]; k++) {
				const uint32_t *g = s.f[fan[a][k]];
				if (fan[a][k] != fi && (g[0] == b || g[1] == b || g[2] == b))
					pair[1] = fan[a][k];
			}
			vec3 mid = v3_scale(v3_add(s.v[a], s.v[b]), 0.5); /* exact */
			for (uint32_t k = 0; k < 6; k++) {
				vec3 org = quantize(v3_madd(mid, rand_unit((uint32_t)(fi * 3 + e) * 6 + k, 50), 2.5));
				if (!enters_all(&s, pair, 2, v3_sub(mid, org)))
					continue;
				check_crossings(m, org, mid, 2, "edge from outside");
				rays++;
			}
			/* A point a third of the way along the edge, near-exact. */
			vec3 third = quantize(v3_add(s.v[a], v3_scale(v3_sub(s.v[b], s.v[a]), 1.0 / 3)));
			check_crossings(m, v3(0, 0, 0), mid, 1, "edge from the centre");
			check_crossings(m, quantize(v3(-0.3, 0.25, 0.1)), mid, 1, "edge from inside");
			check_crossings(m, v3(0, 0, 0), third, 1, "edge third from the centre");
			rays += 3;
		}
	print_message("watertightness: %ld rays through icosphere vertices and edges\n", rays);
	assert_true(rays > 40000);
	object_free(m);
	free(nfan);
	free(fan);
	free(s.v);
	free(s.f);
}

/* A cube [-1,1]^3 with each face an n x n grid of squares split along
 * alternating diagonals: every coordinate is exact, so rays hit edges and
 * vertices exactly, many of them along the axes. */
static struct object *grid_cube(int n, vec3 inside)
{
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH);
	for (int axis = 0; axis < 3; axis++)
		for (int side = -1; side <= 1; side += 2)
			for (int i = 0; i < n; i++)
				for (int j = 0; j < n; j++) {
					uint32_t q[4];
					for (int k = 0; k < 4; k++) {
						double u = -1 + 2.0 * (i + (k == 1 || k == 2)) / n;
						double w = -1 + 2.0 * (j + (k >= 2)) / n;
						double c[3];
						c[axis] = side;
						c[(axis + 1) % 3] = u;
						c[(axis + 2) % 3] = w;
						q[k] = mesh_add_vertex(b, v3(c[0], c[1], c[2]));
					}
					uint32_t f1[3], f2[3];
					if ((i + j) % 2) {
						memcpy(f1, (uint32_t[]){q[0], q[1], q[2]}, sizeof f1);
						memcpy(f2, (uint32_t[]){q[0], q[2], q[3]}, sizeof f2);
					} else {
						memcpy(f1, (uint32_t[]){q[0], q[1], q[3]}, sizeof f1);
						memcpy(f2, (uint32_t[]){q[1], q[2], q[3]}, sizeof f2);
					}
					assert_true(mesh_add_face(b, f1, 0, NULL));
					assert_true(mesh_add_face(b, f2, 0, NULL));
				}
	assert_int_equal(mesh_vertex_count(b), 6 * n * n + 2); /* corners merged */
	mesh_set_inside_vector(b, inside);
	return mesh_new(b, nopos);
}

static void test_mesh_watertight_grid_cube(void **state)
{
	(void)state;
	const int n = 8;
	struct object *m = grid_cube(n, v3(0, 0, 0));
	static const double sl[] = {-0.5, -0.25, 0, 0.125, 0.375};
	long rays = 0;
	/* Targets on the x = -1 face at every grid vertex, edge midpoint and
	 * square centre strictly inside the face; directions entering it. */
	for (int i = 1; i < 2 * n; i++)
		for (int j = 1; j < 2 * n; j++) {
			vec3 p = v3(-1, -1 + (double)i / n, -1 + (double)j / n);
			for (int a = 0; a < 5; a++)
				for (int c = 0; c < 5; c++) {
					vec3 d = v3(1, sl[a], sl[c]);
					check_crossings(m, v3_madd(p, d, -4), p, 2, "cube face point");
					rays++;
				}
			check_crossings(m, v3(0, 0, 0), p, 1, "cube face point from the centre");
			check_crossings(m, v3(0.25, -0.5, 0.75), p, 1, "cube face point from inside");
			rays += 2;
		}
	/* Through the cube's edges and corners, heading inward. */
	for (int j = 0; j <= 2 * n; j++) {
		vec3 p = v3(-1, -1, -1 + (double)j / n);
		vec3 d = v3(1, 0.5, j == 0 ? 0.25 : j == 2 * n ? -0.25 : 0);
		check_crossings(m, v3_madd(p, d, -4), p, 2, "cube edge");
		d = v3(0.5, 1, j == 0 ? 0.5 : j == 2 * n ? -0.5 : 0.125);
		check_crossings(m, v3_madd(p, d, -4), p, 2, "cube edge");
		check_crossings(m, v3(0, 0, 0), p, 1, "cube edge from the centre");
		rays += 3;
	}
	check_crossings(m, v3(-3, -3, -3), v3(-1, -1, -1), 2, "cube diagonal");
	check_crossings(m, v3(3, -3, 3), v3(1, -1, 1), 2, "cube diagonal");
	print_message("watertightness: %ld rays through the grid cube's vertices and edges\n", rays);
	object_free(m);
}

static void test_mesh_inside_vector(void **state)
{
	(void)state;
	struct icosphere s = icosphere(3);
	struct object *m = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(0, 0, 1));
	struct object *hollow = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(0, 0, 0));
	assert_true(object_inside(m, v3(0, 0, 0)));
	assert_true(object_inside(m, v3(0.5, 0.2, -0.3)));
	assert_true(object_inside(m, v3(0, 0, -0.99)));
	assert_false(object_inside(m, v3(2, 0, 0)));
	assert_false(object_inside(m, v3(0, 0, -1.5)));
	assert_false(object_inside(m, v3(0, 0, 1.5)));
	assert_false(object_inside(m, v3(0.9, 0.9, 0)));
	/* Through vertices of the mesh: the pole and any vertex straight above
	 * an inside point. */
	for (size_t i = 0; i < s.nv; i += 7) {
		vec3 below = v3(s.v[i].x, s.v[i].y, s.v[i].z - 0.05);
		if (s.v[i].z > 0.2)
			assert_true(object_inside(m, below));
	}
	/* No inside_vector: no inside. */
	assert_false(object_inside(hollow, v3(0, 0, 0)));
	/* inverse and transforms go through the object layer. */
	struct xform t = xform_translate(v3(10, 0, 0));
	object_transform(m, &t);
	assert_true(object_inside(m, v3(10, 0, 0)));
	assert_false(object_inside(m, v3(0, 0, 0)));
	m->flags |= OBJ_INVERSE;
	assert_false(object_inside(m, v3(10, 0, 0)));
	assert_true(object_inside(m, v3(0, 0, 0)));
	object_free(m);
	object_free(hollow);
	free(s.v);
	free(s.f);

	/* A grid cube with +z: rays leave exactly through top-face vertices
	 * and edges and still count once. */
	m = grid_cube(4, v3(0, 0, 1));
	for (int i = -3; i <= 3; i++)
		for (int j = -3; j <= 3; j++) {
			assert_true(object_inside(m, v3(i * 0.25, j * 0.25, 0)));
			assert_true(object_inside(m, v3(i * 0.25, j * 0.125, -0.75)));
			assert_false(object_inside(m, v3(i * 0.25, j * 0.25, -1.5)));
			assert_false(object_inside(m, v3(i * 0.25 + 2, j * 0.25, 0)));
		}
	object_free(m);
}

static void test_mesh_copy_shares_data(void **state)
{
	(void)state;
	struct icosphere s = icosphere(2);
	struct object *m = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(1, 0, 0));
	struct texture *tex = texture_new();
	m->tex = texture_ref(tex);
	struct mesh_stats a, b;
	mesh_get_stats(m, &a);
	assert_int_equal(a.refs, 1);
	struct object *copies[100];
	for (int i = 0; i < 100; i++) {
		copies[i] = object_copy(m);
		struct xform t = xform_translate(v3(3.0 * i, 0, 0));
		object_transform(copies[i], &t);
	}
	mesh_get_stats(copies[99], &b);
	assert_ptr_equal(a.data, b.data);
	assert_int_equal(b.refs, 101);
	assert_int_equal(a.bytes, b.bytes);
	assert_int_equal(tex->refs, 102);
	object_free(m);
	/* The copies keep working after the original is gone. */
	for (int i = 0; i < 100; i++) {
		struct hit h = must_hit(copies[i], v3(3.0 * i, 0, -5), v3(0, 0, 1), 0);
		assert_near(h.t, 4, 0.01);
		assert_true(object_inside(copies[i], v3(3.0 * i, 0, 0)));
		assert_false(object_inside(copies[i], v3(3.0 * i + 1.5, 0, 0)));
	}
	mesh_get_stats(copies[0], &b);
	assert_int_equal(b.refs, 100);
	for (int i = 0; i < 100; i++)
		object_free(copies[i]);
	assert_int_equal(tex->refs, 1);
	texture_unref(tex);
	free(s.v);
	free(s.f);
}

static void test_mesh_uv_normals_textures(void **state)
{
	(void)state;
	struct texture *t0 = texture_new(), *t1 = texture_new(), *t2 = texture_new();
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH);
	/* Two triangles of mesh { }: corners given by value share entries. */
	uint32_t v[6] = {mesh_add_vertex(b, v3(0, 0, 0)), mesh_add_vertex(b, v3(1, 0, 0)), mesh_add_vertex(b, v3(0, 1, 0)),
	                 mesh_add_vertex(b, v3(1, 0, 0)), mesh_add_vertex(b, v3(1, 1, 0)), mesh_add_vertex(b, v3(0, 1, -0.0))};
	assert_int_equal(v[3], v[1]);
	assert_int_equal(v[5], v[2]);
	assert_int_equal(mesh_vertex_count(b), 4);
	uint32_t tx[3] = {mesh_add_texture(b, t0), mesh_add_texture(b, t1), mesh_add_texture(b, t0)};
	assert_int_equal(tx[2], tx[0]);
	assert_int_equal(mesh_texture_count(b), 2);
	assert_true(mesh_add_face(b, v, 1, (uint32_t[]){tx[1]}));
	uint32_t tt[3] = {tx[0], tx[1], mesh_add_texture(b, t2)};
	assert_true(mesh_add_face(b, v + 3, 3, tt));
	/* Out-of-range indices are refused. */
	assert_false(mesh_add_face(b, (uint32_t[]){0, 1, 4}, 0, NULL));
	assert_false(mesh_add_face(b, v, 1, (uint32_t[]){3}));
	assert_false(mesh_add_face(b, v, 2, tt));
	assert_int_equal(mesh_face_count(b), 2);
	/* Face 0: uv vectors and smooth normals; face 1: flat, no uv. */
	uint32_t uv[3] = {mesh_add_uv(b, 0, 0), mesh_add_uv(b, 1, 0), mesh_add_uv(b, 0.5, 2)};
	assert_true(mesh_set_face_uvs(b, 0, uv));
	assert_false(mesh_set_face_uvs(b, 2, uv));
	assert_false(mesh_set_face_uvs(b, 0, (uint32_t[]){0, 1, 3}));
	uint32_t nn[3] = {mesh_add_normal(b, v3(10, 0, -10)), mesh_add_normal(b, v3(-1, 0, -1)),
	                  mesh_add_normal(b, v3(0, 0, -3))};
	assert_true(mesh_set_face_normals(b, 0, nn));
	/* A degenerate face is dropped. */
	uint32_t dv = mesh_add_vertex(b, v3(2, 0, 0));
	assert_true(mesh_add_face(b, (uint32_t[]){v[0], v[1], dv}, 0, NULL));
	struct object *m = mesh_new(b, nopos);
	assert_int_equal(t1->refs, 2);
	struct mesh_stats st;
	mesh_get_stats(m, &st);
	assert_int_equal(st.triangles, 2);

	/* Face 0 at (0.25, 0.5): weights a 0.25, b 0.25, c 0.5. */
	struct hit h = must_hit(m, v3(0.25, 0.5, -1), v3(0, 0, 1), 0);
	assert_near(h.t, 1, 0);
	double w[3];
	struct texture *tl[3];
	assert_int_equal(mesh_textures_at(m, &h, tl, w), 1);
	assert_ptr_equal(tl[0], t1);
	assert_ptr_equal(m->ops->texture_at(m, &h), t1);
	double uvv[2];
	assert_true(m->ops->uv(m, v3(0.25, 0.5, 0), &h, uvv));
	assert_near(uvv[0], 0.25 * 1 + 0.5 * 0.5, 1e-15);
	assert_near(uvv[1], 0.5 * 2, 1e-15);
	vec3 ex = v3_norm(v3(0.25 * M_SQRT1_2 - 0.25 * M_SQRT1_2, 0, -0.25 * M_SQRT1_2 - 0.25 * M_SQRT1_2 - 0.5));
	vec3 n = object_normal(m, v3(0.25, 0.5, 0), &h);
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-15);
	/* Without a hit record: found from the point. */
	n = object_normal(m, v3(0.25, 0.5, 0), NULL);
	assert_vec_near(n, ex.x, ex.y, ex.z, 1e-15);

	/* Face 1 at (0.75, 0.75): three textures with their weights, uv <0,0>,
	 * the flat normal. */
	h = must_hit(m, v3(0.75, 0.75, 1), v3(0, 0, -1), 0);
	assert_int_equal(mesh_textures_at(m, &h, tl, w), 3);
	assert_ptr_equal(tl[0], t0);
	assert_ptr_equal(tl[1], t1);
	assert_ptr_equal(tl[2], t2);
	assert_near(w[0] + w[1] + w[2], 1, 1e-15);
	assert_near(w[1], 0.5, 1e-15); /* b = (1,1,0) */
	assert_ptr_equal(m->ops->texture_at(m, &h), t0);
	assert_true(m->ops->uv(m, v3(0.75, 0.75, 0), &h, uvv));
	assert_near(uvv[0], 0, 0);
	assert_near(uvv[1], 0, 0);
	n = object_normal(m, v3(0.75, 0.75, 0), &h);
	assert_near(fabs(n.z), 1, 0);

	object_free(m);
	assert_int_equal(t0->refs, 1);
	assert_int_equal(t1->refs, 1);
	assert_int_equal(t2->refs, 1);
	texture_unref(t0);
	texture_unref(t1);
	texture_unref(t2);
}

static void test_mesh2_default_indices(void **state)
{
	(void)state;
	/* mesh2 with as many normals and uv vectors as vertices and no index
	 * lists: the face indices serve for both. No merging in mesh2. (The
	 * last normal differs, so that the face is not flattened as one with
	 * three equal normals.) */
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH2);
	vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
	for (int i = 0; i < 4; i++) {
		assert_int_equal(mesh_add_vertex(b, p[i]), i);
		assert_int_equal(mesh_add_normal(b, v3(0, i == 3 ? 0.001 : 0, 1)), i);
		assert_int_equal(mesh_add_uv(b, i, 10 * i), i);
	}
	struct texture *t = texture_new();
	assert_int_equal(mesh_add_texture(b, t), 0);
	assert_int_equal(mesh_add_texture(b, t), 1);
	texture_unref(t); /* the builder holds its own references */
	assert_true(mesh_add_face(b, (uint32_t[]){0, 1, 3}, 0, NULL));
	struct object *m = mesh_new(b, nopos);
	struct hit h = must_hit(m, v3(0.25, 0.5, 1), v3(0, 0, -1), 0);
	double uv[2];
	assert_true(m->ops->uv(m, v3(0.25, 0.5, 0), &h, uv));
	assert_near(uv[0], 0.25 * 1 + 0.5 * 3, 1e-15);
	assert_near(uv[1], 0.25 * 10 + 0.5 * 30, 1e-15);
	assert_vec_near(object_normal(m, v3(0.25, 0.5, 0), &h), 0, 0.0005, 1, 1e-6);
	assert_null(m->ops->texture_at(m, &h));
	object_free(m);

	/* Normal indices for the first face only: the second is flat. */
	b = mesh_builder_new(MESH_KIND_MESH2);
	for (int i = 0; i < 4; i++)
		mesh_add_vertex(b, v3(i & 1, i >> 1, 0));
	mesh_add_normal(b, v3(0, 1, -1));
	mesh_add_normal(b, v3(0, -1, -1));
	assert_true(mesh_add_face(b, (uint32_t[]){0, 1, 2}, 0, NULL));
	assert_true(mesh_add_face(b, (uint32_t[]){1, 3, 2}, 0, NULL));
	assert_true(mesh_set_face_normals(b, 0, (uint32_t[]){0, 1, 0}));
	assert_false(mesh_set_face_normals(b, 1, (uint32_t[]){0, 2, 0}));
	m = mesh_new(b, nopos);
	h = must_hit(m, v3(0.25, 0.25, -1), v3(0, 0, 1), 0);
	/* 3/4 of the first normal and 1/4 of the second: (0, 1, -2) / sqrt 5 */
	assert_vec_near(v3_norm(object_normal(m, v3(0.25, 0.25, 0), &h)), 0, 1 / sqrt(5), -2 / sqrt(5), 1e-15);
	h = must_hit(m, v3(0.75, 0.75, -1), v3(0, 0, 1), 0);
	assert_near(fabs(v3_norm(object_normal(m, v3(0.75, 0.75, 0), &h)).z), 1, 0);
	object_free(m);

	/* A builder abandoned after a parse error releases its textures. */
	b = mesh_builder_new(MESH_KIND_MESH2);
	t = texture_new();
	mesh_add_texture(b, t);
	assert_int_equal(t->refs, 2);
	mesh_builder_free(b);
	assert_int_equal(t->refs, 1);
	texture_unref(t);
}

static void test_mesh_empty_and_transformed(void **state)
{
	(void)state;
	/* No faces, or only degenerate ones: never hit, finite point bounds. */
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH2);
	struct object *m = mesh_new(b, nopos);
	assert_false(hits(m, v3(0, 0, -1), v3(0, 0, 1), 0, INFINITY, NULL));
	assert_false(object_inside(m, v3(0, 0, 0)));
	struct aabb bb = object_world_bounds(m);
	assert_true(aabb_is_finite(bb));
	object_free(m);
	b = mesh_builder_new(MESH_KIND_MESH);
	uint32_t v[3] = {mesh_add_vertex(b, v3(0, 0, 0)), mesh_add_vertex(b, v3(1, 0, 0)), mesh_add_vertex(b, v3(2, 0, 0))};
	assert_true(mesh_add_face(b, v, 0, NULL));
	mesh_set_inside_vector(b, v3(0, 1, 0));
	m = mesh_new(b, nopos);
	assert_false(hits(m, v3(0.5, 0, -1), v3(0, 0, 1), 0, INFINITY, NULL));
	assert_false(object_inside(m, v3(0.5, -1, 0)));
	object_free(m);

	/* A transformed icosphere: the same t as the sphere it approximates
	 * along a vertex direction, bounds and normals in world space. */
	struct icosphere s = icosphere(2);
	m = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(0, 1, 0));
	bb = m->ops->bounds(m);
	assert_near(bb.lo.x, -1, 1e-6);
	assert_near(bb.hi.z, 1, 1e-6);
	struct xform sc = xform_scale(v3(2, 2, 2)), tr = xform_translate(v3(0, 0, 10));
	object_transform(m, &sc);
	object_transform(m, &tr);
	/* Down onto the vertex along (0, 1, phi): it is entered exactly there. */
	vec3 pole = s.v[5];
	vec3 world = v3(2 * pole.x, 2 * pole.y, 2 * pole.z + 10);
	struct hit h = must_hit(m, v3(4 * pole.x, 4 * pole.y, 4 * pole.z + 10), v3_scale(pole, -2), 0);
	assert_near(h.t, 1, 1e-12);
	vec3 n = object_normal(m, world, &h);
	assert_true(v3_dot(n, v3_norm(pole)) > 0.95 || v3_dot(n, v3_norm(pole)) < -0.95);
	bb = object_world_bounds(m);
	assert_near(bb.lo.z, 8, 1e-5);
	assert_near(bb.hi.z, 12, 1e-5);
	assert_true(object_inside(m, v3(0, 0, 10)));
	assert_false(object_inside(m, v3(0, 0, 0)));
	/* Rays far from the mesh still hit it exactly where brute force does. */
	struct ray r = mkray(v3(1e6, 3e5, -2e6), v3_sub(v3(0.1, 0.2, 0.3), v3(1e6, 3e5, -2e6)));
	struct tri_hit bh;
	size_t bp;
	object_free(m);
	m = mesh_from(s.v, s.nv, (const uint32_t (*)[3])s.f, s.nf, v3(0, 0, 0));
	assert_true(m->ops->intersect(m, &r, 0, INFINITY, &h));
	assert_true(brute_closest(m, &r, 0, INFINITY, &bh, &bp));
	assert_true(h.t == bh.t);
	object_free(m);
	free(s.v);
	free(s.f);
}

/* A 1M-triangle height-field grid: its build time is printed (not
 * asserted), its memory must stay well under 245 MB. */
/* Large enough for every part of the build to run on two threads (the
 * sort, the clusters, the upper levels), with scales that differ by 10^4
 * (a huge triangle among small ones, a far cluster) and 3000 copies of
 * one triangle (equal Morton codes): the closest hit still agrees with
 * brute force. */
static void test_mesh_threaded_matches_brute_force(void **state)
{
	(void)state;
	size_t nsoup = 90000, ncopy = 3000, nf = nsoup + ncopy + 1, nv = 3 * nf;
	vec3 *v = malloc(nv * sizeof *v);
	uint32_t (*f)[3] = malloc(nf * sizeof *f);
	for (size_t i = 0; i < nf; i++) {
		vec3 c = v3(4 * urand((uint32_t)i, 31) - 2, 4 * urand((uint32_t)i, 32) - 2, 4 * urand((uint32_t)i, 33) - 2);
		double size = 0.01 + 0.05 * urand((uint32_t)i, 34);
		if (i >= nsoup && i < nsoup + ncopy) { /* the stack of copies */
			c = v3(0.5, 0.5, 0.5);
			size = 0.2;
		} else if (i == nf - 1) { /* one huge triangle */
			c = v3(0, 0, 0);
			size = 100;
		} else if (i % 1000 == 0) /* a far, sparse cluster */
			c = v3_add(c, v3(300, 0, 0));
		for (int k = 0; k < 3; k++) {
			uint32_t seed = i >= nsoup && i < nsoup + ncopy ? (uint32_t)(3 * nsoup + k) : (uint32_t)(3 * i + k);
			v[3 * i + k] = v3_madd(c, rand_unit(seed, 40), size);
			f[i][k] = (uint32_t)(3 * i + k);
		}
	}
	struct object *m = mesh_from(v, nv, f, nf, v3(0, 0, 0));
	struct mesh_stats st;
	mesh_get_stats(m, &st);
	assert_int_equal(st.triangles, nf);
	assert_true(st.nodes < 2 * nf);
	int nhit = 0;
	for (uint32_t i = 0; i < 600; i++) {
		vec3 org = v3(8 * urand(i, 50) - 4, 8 * urand(i, 51) - 4, 8 * urand(i, 52) - 4);
		vec3 dir = rand_unit(i, 53);
		if (i % 3 == 0) /* through the stack of copies */
			dir = v3_sub(v3(0.5, 0.5, 0.5), org);
		struct ray r = mkray(org, dir);
		struct hit h;
		struct tri_hit bh;
		size_t bp = 0;
		bool a = m->ops->intersect(m, &r, 0, INFINITY, &h);
		bool b = brute_closest(m, &r, 0, INFINITY, &bh, &bp);
		if (a != b)
			fail_msg("ray %u: mesh %d, brute force %d", i, a, b);
		if (a && h.t != bh.t)
			fail_msg("ray %u: mesh t %.17g, brute force %.17g", i, h.t, bh.t);
		nhit += a;
	}
	print_message("%d of 600 rays hit\n", nhit);
	assert_true(nhit > 200);
	object_free(m);
	free(v);
	free(f);
}

static void test_mesh_million(void **state)
{
	(void)state;
	const int g = 708; /* 2 * 708^2 = 1,002,528 triangles */
	struct mesh_builder *b = mesh_builder_new(MESH_KIND_MESH2);
	for (int j = 0; j <= g; j++)
		for (int i = 0; i <= g; i++)
			mesh_add_vertex(b, v3(i, 0.3 * sin(i * 0.1) * cos(j * 0.13), j));
	for (int j = 0; j < g; j++)
		for (int i = 0; i < g; i++) {
			uint32_t a = (uint32_t)(j * (g + 1) + i), c = a + (uint32_t)g + 1;
			assert_true(mesh_add_face(b, (uint32_t[]){a, a + 1, c + 1}, 0, NULL));
			assert_true(mesh_add_face(b, (uint32_t[]){a, c + 1, c}, 0, NULL));
		}
	struct timespec t0, t1;
	timespec_get(&t0, TIME_UTC);
	struct object *m = mesh_new(b, nopos);
	timespec_get(&t1, TIME_UTC);
	struct mesh_stats st;
	mesh_get_stats(m, &st);
	double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
	print_message("mesh of %zu triangles, %zu vertices: %zu nodes, %.1f MB, built in %.3f s\n", st.triangles,
	              st.vertices, st.nodes, (double)st.bytes / 1e6, secs);
	assert_int_equal(st.triangles, 2 * g * g);
	assert_true(st.bytes < 150u * 1000 * 1000);
	/* A few rays straight down hit the surface at the analytic height. */
	for (int k = 0; k < 100; k++) {
		double x = 1 + 7.03 * k, z = 700 - 6.91 * k;
		struct hit h = must_hit(m, v3(x, 5, z), v3(0, -1, 0), 0);
		assert_near(5 - h.t, 0.3 * sin(x * 0.1) * cos(z * 0.13), 0.01);
	}
	object_free(m);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_tri_basic),
		cmocka_unit_test(test_tri_shared_edge_exactly_once),
		cmocka_unit_test(test_triangle_hit_miss),
		cmocka_unit_test(test_triangle_transformed),
		cmocka_unit_test(test_triangle_degenerate),
		cmocka_unit_test(test_smooth_triangle),
		cmocka_unit_test(test_mesh_matches_brute_force),
		cmocka_unit_test(test_mesh_watertight_icosphere),
		cmocka_unit_test(test_mesh_watertight_grid_cube),
		cmocka_unit_test(test_mesh_inside_vector),
		cmocka_unit_test(test_mesh_copy_shares_data),
		cmocka_unit_test(test_mesh_uv_normals_textures),
		cmocka_unit_test(test_mesh2_default_indices),
		cmocka_unit_test(test_mesh_empty_and_transformed),
		cmocka_unit_test(test_mesh_threaded_matches_brute_force),
		cmocka_unit_test(test_mesh_million),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

/* test_heightfield.c: unit tests for the height field
 * (src/geom/heightfield.c). The expected values were measured with
 * POV-Ray 3.7's trace(), inside(), min_extent() and max_extent() on
 * height_field { function W, H { ... } } objects, e.g.
 *   #declare H = height_field { function 3, 3 { x } }
 *   #declare N = <0,0,0>;
 *   #declare P = trace(H, <0.3,5,0.4>, -y, N);
 * printed to 10 digits (bounds to 8). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include "geom/heightfield.h"
#include "scene/object.h"

#include <math.h>
#include <stdlib.h>

#include "testutil.h"
#include "shapetest.h"

static const struct srcpos nopos = {0, 0, 0};

/* A w x h field of f(x, y) sampled as POV-Ray samples a function:
 * column c at x = c / (w - 1), row r at y = r / (h - 1). */
static struct object *field(int w, int h, double (*f)(double, double))
{
	uint16_t *v = malloc((size_t)w * h * sizeof *v);
	for (int r = 0; r < h; r++)
		for (int c = 0; c < w; c++)
			v[r * w + c] = heightfield_quantize(f((double)c / (w - 1), (double)r / (h - 1)));
	struct object *o = heightfield_new(w, h, v, nopos);
	free(v);
	object_prepare(o);
	return o;
}

static double fx(double x, double y) { (void)y; return x; }
static double fy(double x, double y) { (void)x; return y; }
static double fc(double x, double y) { (void)x; (void)y; return 0.3; }
static double fcorner(double x, double y) { return (x >= 0.5 && y < 0.5) ? 1 : 0; }
static double fwrap(double x, double y) { (void)y; return 1.5 * x - 0.2; }

static void test_function_fields(void **state)
{
	(void)state;
	struct object *o = field(3, 3, fx);
	check_hit(o, v3(0.3, 5, 0.4), v3(0, -1, 0), v3(0.3, 0.2999908447, 0.4), v3(-0.7070959913, 0.7071175709, 0));
	struct aabb b = object_world_bounds(o);
	assert_vec_near(b.lo, 0, 0, 0, 1e-7);
	assert_vec_near(b.hi, 1, 0.99998480, 1, 1e-7);
	/* Inside is below the surface, without end, over the square only. */
	assert_true(object_inside(o, v3(0.3, 0.29, 0.4)));
	assert_false(object_inside(o, v3(0.3, 0.31, 0.4)));
	assert_true(object_inside(o, v3(0.3, -100, 0.4)));
	assert_false(object_inside(o, v3(1.1, 0.1, 0.5)));
	/* From below, the same surface. */
	check_hit(o, v3(0.3, -5, 0.4), v3(0, 1, 0), v3(0.3, 0.2999908447, 0.4), v3(-0.7070959913, 0.7071175709, 0));
	object_free(o);
	/* The function's y runs toward -z. */
	o = field(3, 3, fy);
	check_hit(o, v3(0.3, 5, 0.4), v3(0, -1, 0), v3(0.3, 0.5999847412, 0.4), v3(0, 0.7071067812, 0.7071067812));
	object_free(o);
	/* 16-bit quantisation: 0.3 is 19660 / 65536; no sides. */
	o = field(3, 3, fc);
	check_hit(o, v3(0.3, 5, 0.4), v3(0, -1, 0), v3(0.3, 0.2999877930, 0.4), v3(0, 1, 0));
	assert_false(hits(o, v3(0.3, 0.1, 0.4), v3(1, 0, 0), 0, INFINITY));
	/* POV-Ray's depth tolerance of 1e-4. */
	assert_true(hits(o, v3(0.3, 0.2999877930 + 0.00011, 0.4), v3(0, -1, 0), 0, INFINITY));
	assert_false(hits(o, v3(0.3, 0.2999877930 + 0.00007, 0.4), v3(0, -1, 0), 0, INFINITY));
	object_free(o);
	/* The diagonal of each square runs from (x+1, z) to (x, z+1). */
	o = field(2, 2, fcorner);
	check_hit(o, v3(0.3, 5, 0.4), v3(0, -1, 0), v3(0.3, 0, 0.4), v3(0, 1, 0));
	check_hit(o, v3(0.7, 5, 0.4), v3(0, -1, 0), v3(0.7, 0.0999984741, 0.4),
	          v3(-0.5773473326, 0.5773561423, -0.5773473326));
	object_free(o);
	/* Values wrap to 16 bits: -0.2 is 0.8. */
	o = field(3, 3, fwrap);
	check_hit(o, v3(0.01, 5, 0.4), v3(0, -1, 0), v3(0.01, 0.7950027466, 0.4), v3(0.4472354317, 0.8944162726, 0));
	b = object_world_bounds(o);
	assert_near(b.lo.y, 0.29997250, 1e-7);
	assert_near(b.hi.y, 0.80000305, 1e-7);
	object_free(o);
}

static void test_water_level(void **state)
{
	(void)state;
	struct object *o = field(3, 3, fx);
	heightfield_set_water_level(o, 0.4);
	assert_false(hits(o, v3(0.3, 5, 0.4), v3(0, -1, 0), 0, INFINITY));
	assert_false(hits(o, v3(0.38, 5, 0.4), v3(0, -1, 0), 0, INFINITY));
	check_hit(o, v3(0.41, 5, 0.4), v3(0, -1, 0), v3(0.41, 0.4099874878, 0.4), v3(-0.7070959913, 0.7071175709, 0));
	struct aabb b = object_world_bounds(o);
	assert_near(b.lo.y, 0.4, 1e-7);
	assert_near(b.hi.y, 0.99998474, 1e-7);
	object_free(o);
	/* Water above every height: POV-Ray's box turns over. */
	o = field(3, 3, fc);
	heightfield_set_water_level(o, 0.5);
	assert_false(hits(o, v3(0.3, 5, 0.4), v3(0, -1, 0), 0, INFINITY));
	b = object_world_bounds(o);
	assert_near(b.lo.y, 0.29998779, 1e-7);
	assert_near(b.hi.y, 0.5, 1e-7);
	object_free(o);
}

int main(void)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_function_fields),
		cmocka_unit_test(test_water_level),
	};
	return cmocka_run_group_tests(tests, NULL, NULL);
}

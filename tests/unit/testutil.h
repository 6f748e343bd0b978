/* testutil.h: assertions shared by the cmocka unit tests. Include after
 * <cmocka.h> and "math/vec.h". */
#ifndef LUCENT_TESTUTIL_H
#define LUCENT_TESTUTIL_H

#include <math.h>

/* cmocka's assert_float_equal works in single precision; these keep the
 * full double and print both values on failure. */
#define assert_near(a, b, tol)                                                       \
	do {                                                                         \
		double a_ = (a), b_ = (b), tol_ = (tol);                             \
		if (!(fabs(a_ - b_) <= tol_))                                        \
			fail_msg("%s = %.17g, expected %.17g (tolerance %g)", #a, a_, b_, tol_); \
	} while (0)

#define assert_vec_near(v, ex, ey, ez, tol)                                          \
	do {                                                                         \
		vec3 v_ = (v);                                                       \
		assert_near(v_.x, (ex), (tol));                                      \
		assert_near(v_.y, (ey), (tol));                                      \
		assert_near(v_.z, (ez), (tol));                                      \
	} while (0)

#endif

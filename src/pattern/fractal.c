/* fractal.c: the fractal patterns (see kinds.h). IN PROGRESS: being written. */
#include "pattern/kinds.h"

PATTERN_FN(julia)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(mandel)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(magnet)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

/* tiling.c: tiling and pavement (see kinds.h). IN PROGRESS: being written. */
#include "pattern/kinds.h"

PATTERN_FN(tiling)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(pavement)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

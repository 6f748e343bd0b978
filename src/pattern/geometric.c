/* geometric.c: the patterns defined by geometry (see kinds.h). IN PROGRESS: being written. */
#include "pattern/kinds.h"

PATTERN_FN(checker)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(hexagon)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(brick)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(cubic)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(square)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(triangular)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(object)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(boxed)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(cylindrical)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(spherical)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(planar)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(gradient)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(onion)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(radial)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(spiral1)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(spiral2)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(quilted)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(leopard)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(slope)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(aoi)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(function)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(pigment)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

PATTERN_FN(image)
{
	(void)pt; (void)q; (void)ctx;
	return 0;
}

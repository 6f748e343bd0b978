/* fn_internal.c: POV-Ray's internal functions (function { internal(N) }),
 * numbered as POV-Ray numbers them. (Being written.) */
#include "scene/fn.h"

#include <math.h>

double fn_internal(int n, const double *args, int nargs)
{
	(void)n;
	(void)args;
	(void)nargs;
	return NAN;
}

int fn_internal_params(int n)
{
	(void)n;
	return -1;
}

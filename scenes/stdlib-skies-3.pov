// stdlib-skies-3.pov: the sky_sphere S_Cloud3 of skies.inc alone, seen as
// in stdlib-skies.pov (the camera looks at the horizon).
#declare Sky = 3;
#declare Swatches = false;
#include "stdlib-skies.pov"

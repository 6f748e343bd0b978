// stdlib-skies-4.pov: the sky_sphere S_Cloud4 of skies.inc alone, seen as
// in stdlib-skies.pov (the camera looks at the horizon).
#declare Sky = 4;
#declare Swatches = false;
#include "stdlib-skies.pov"

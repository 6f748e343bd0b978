// stdlib-skies-5.pov: the sky_sphere S_Cloud5 of skies.inc alone, seen as
// in stdlib-skies.pov (the camera looks at the horizon).
#declare Sky = 5;
#declare Swatches = false;
#include "stdlib-skies.pov"

// stdlib-skies-2.pov: the sky_sphere S_Cloud2 of skies.inc alone, seen as
// in stdlib-skies.pov (the camera looks at the horizon).
#declare Sky = 2;
#declare Swatches = false;
#include "stdlib-skies.pov"

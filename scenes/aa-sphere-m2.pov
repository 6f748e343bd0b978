// aa-sphere-m2.pov: aa-sphere.pov, rendered with method 2 (sampling.list).
#include "aa-sphere.pov"

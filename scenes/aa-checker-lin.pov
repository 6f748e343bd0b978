// aa-checker-lin.pov: aa-checker.pov (included through +Lscenes) with other antialiasing
// switches (tests/render/sampling.list).
#include "aa-checker.pov"

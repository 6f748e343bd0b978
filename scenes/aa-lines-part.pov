// aa-lines-part.pov: aa-lines.pov (included through +Lscenes) with other antialiasing
// switches (tests/render/sampling.list).
#include "aa-lines.pov"

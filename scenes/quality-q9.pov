// quality-q9.pov: quality-levels.inc at +Q9 (tests/render/sampling.list).
#include "quality-levels.inc"

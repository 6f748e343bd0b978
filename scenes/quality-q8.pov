// quality-q8.pov: quality-levels.inc at +Q8 (tests/render/sampling.list).
#include "quality-levels.inc"

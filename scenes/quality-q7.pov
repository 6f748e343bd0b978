// quality-q7.pov: quality-levels.inc at +Q7 (tests/render/sampling.list).
#include "quality-levels.inc"

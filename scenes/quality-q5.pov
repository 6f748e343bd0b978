// quality-q5.pov: quality-levels.inc at +Q5 (tests/render/sampling.list).
#include "quality-levels.inc"

// quality-q6.pov: quality-levels.inc at +Q6 (tests/render/sampling.list).
#include "quality-levels.inc"

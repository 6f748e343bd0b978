// quality-q3.pov: quality-levels.inc at +Q3 (tests/render/sampling.list).
#include "quality-levels.inc"

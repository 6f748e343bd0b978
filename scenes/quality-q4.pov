// quality-q4.pov: quality-levels.inc at +Q4 (tests/render/sampling.list).
#include "quality-levels.inc"

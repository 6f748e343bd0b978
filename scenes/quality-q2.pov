// quality-q2.pov: quality-levels.inc at +Q2 (tests/render/sampling.list).
#include "quality-levels.inc"

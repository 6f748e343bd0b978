// quality-q0.pov: quality-levels.inc at +Q0 (tests/render/sampling.list).
#include "quality-levels.inc"

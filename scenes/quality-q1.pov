// quality-q1.pov: quality-levels.inc at +Q1 (tests/render/sampling.list).
#include "quality-levels.inc"

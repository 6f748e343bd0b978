// expect: 13:1: #error: done
// Found by fuzzing (a hang in CI's run): crackle's search stepped through the
// cubes around the point by adding 1 to the cube's coordinate, which past 2^53
// does not change it, so f_crackle(6.7e71, ...) never returned; so did
// pavement's hexagons and the penrose tiling. They count whole offsets now.
// (Past 2^31, POV-Ray's cube coordinates are ints and its values differ from
// lucent's; up to there they agree.)
#version 3.7;
#include "functions.inc"
#declare A = f_crackle(6.7e71, 1.3, -0.8) + f_crackle(-1e300, 1e300, 3);
#declare P = function { pattern { pavement number_of_sides 6 } }
#declare T = function { pattern { tiling 27 } } #declare B = P(1e300, 0, -1e300) + T(1e300, 0, 1e300);
#error "done"

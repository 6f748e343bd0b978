// expect: 19:1: #error: done
// Found by fuzz_parse (run 17): f_crackle at an infinite coordinate (1e315)
// wrapped NaN into an int, undefined behaviour. The same cast was in the
// square and triangular patterns, noise_generator 3's lattice, the Penrose
// pentagons (past an int's range) and f_hetero_mf/f_ridge's fractional
// octaves (-1e300); all are checked now.
#version 3.7;
#include "functions.inc"
#declare Inf = 1e300 * 1e300;
#declare A = f_crackle(-1e300, 1e315, 3) + f_crackle(Inf, 0, -Inf);
#declare Sq = function { pattern { square } }
#declare Tr = function { pattern { triangular } }
#declare Bz = function { pattern { bozo noise_generator 3 } }
#declare T25 = function { pattern { tiling 25 } }
#declare C = Sq(Inf, 0, 1) + Tr(-Inf, 0, 1) + Bz(Inf, 1, 1) + T25(1e300, 0, 1) + T25(Inf, 0, -Inf);
#declare H = f_hetero_mf(1, 2, 3, 0.5, 2, -1e300, 0.3, 1, 0)
  + f_ridged_mf(1, 2, 3, 0.5, 2, -1e300, 1, 2, 0) + f_ridged_mf(1, 2, 3, 0.5, 2, 1e300, 1, 2, 0);
#declare R = f_ridge(1, 2, 3, 2, -1e300, 0.5, 0.5, 0.5, 0) + f_ridge(1, 2, 3, 2, -2.5, 0.5, 0.5, 0.5, 0);
#error "done"

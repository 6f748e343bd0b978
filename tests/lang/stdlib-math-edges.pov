// math.inc: the float functions used inside other functions, and edge
// cases of the macros.
#version 3.7;
#include "math.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 9), "\n") #end
#macro V3(N, V) #debug concat(N, " ", vstr(3, V, ",", 0, 9), "\n") #end
#declare F = function { clamp(x, -1, 1) + clip(y, 0, 1) * 10 + sgn(z) * 100 + f_sqr(max3(x, y, z)) * 1000 }
S("F", F(2.5, 0.5, -3))
S("F", F(-0.25, 7, 0))
#declare G = function { sind(x) + cosd(y) + atan2d(x, y) + even(z) + odd(z + 1) + adj_range2(x, 0, 90, 0, 1) }
S("G", G(30, 60, 4))
S("G", G(-45, 135, 3))
S("min3", min3(4, 4, 4)) S("max3", max3(-1, -2, -3))
S("Interp rev", Interpolate(0.25, 1, 0, 10, 20, 1))
S("Interp neg", Interpolate(-0.5, -1, 1, -10, 10, 3))
#declare One = array[1] {7}
S("Mean one", Mean(One))
S("Std_Dev one", Std_Dev(One, 7))
GetStats(One)
#declare Neg = array[4] {-3, -1.5, 2, 0.25}
GetStats(Neg)
S("Std_Dev other mean", Std_Dev(Neg, 1))
V3("VPerp ties", VPerp_To_Vector(<2, 2, 2>))
V3("VPerp ties", VPerp_To_Vector(<-1, 3, -1>))
V3("VPerp ties", VPerp_To_Vector(<0.5, 4, 4>))
S("VAngleD same", VAngleD(<1, 2, 3>, <2, 4, 6>))
S("VAngleD opposite", VAngleD(<1, 2, 3>, <-2, -4, -6>))
S("VRotationD", VRotationD(<0, 0, 1>, <1, 0, 0>, y))
S("VRotationD", VRotationD(<0, 0, 1>, <1, 0, 0>, -y))
S("VEq close", VEq(<1, 2, 3>, <1, 2, 3 + 1e-12>))
V3("VWith_Len neg", VWith_Len(<0, 0, -3>, -2))
// Zero vectors: POV-Ray normalizes them to zero (with a warning).
S("VAngleD zero", VAngleD(<0, 0, 0>, x))
V3("VWith_Len zero", VWith_Len(<0, 0, 0>, 2))
V3("VPerp_To_Plane parallel", VPerp_To_Plane(<1, 2, 3>, <2, 4, 6>))

// math.inc: the float functions and float macros (Histogram is in
// stdlib-math-histogram: POV-Ray 3.7's own fails).
#version 3.7;
#include "math.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 9), "\n") #end
#macro V3(N, V) #debug concat(N, " ", vstr(3, V, ",", 0, 9), "\n") #end
#macro V5(N, V) #debug concat(N, " ", vstr(5, V, ",", 0, 9), "\n") #end
#for (I, -3, 3) S(concat("even ",str(I,0,1)), even(I)) S("odd", odd(I)) #end
S("even 2.5", even(2.5)) S("odd 2.5", odd(2.5)) S("even -2.5", even(-2.5)) S("odd -1.5", odd(-1.5)) S("odd 1.5", odd(1.5)) S("even 1.5", even(1.5))
S("sgn 0", sgn(0)) S("sgn -2", sgn(-2)) S("sgn 3", sgn(3))
#for (I, -4, 4, 0.75) S(concat("clamp ",str(I,0,2)), clamp(I, -1, 2)) S("clip", clip(I,-1,2)) #end
S("clamp rev", clamp(0.5, 2, -1))
S("clip rev", clip(0.5, 2, -1)) S("clip rev2", clip(3, 2, -1))
S("adj_range", adj_range(0.25, 2, 6)) S("adj_range2", adj_range2(3, 1, 5, 10, 20))
S("max3", max3(1,3,2)) S("min3", min3(2,-1,3)) S("f_sqr", f_sqr(-3))
S("sind", sind(30)) S("cosd", cosd(60)) S("tand", tand(45)) S("asind", asind(0.5)) S("acosd", acosd(0.5)) S("atand", atand(1)) S("atan2d", atan2d(1, -1))
#for (M, -2, 3) S(concat("Interp ", str(M,0,0)), Interpolate(0.25, 0, 1, 10, 20, M)) #end
S("Interp half", Interpolate(0.5, 0, 1, 10, 20, 0.5))
S("Interp out", Interpolate(1.5, 0, 1, 10, 20, 1))
S("Interp out2", Interpolate(1.5, 0, 1, 10, 20, 2))
S("Interp out0", Interpolate(1.5, 0, 1, 10, 20, 0))
#declare A = array[5] {1, 2, 4, 8, 5}
S("Mean", Mean(A))
S("Std_Dev", Std_Dev(A, Mean(A)))
#declare AV = array[3] {<1,2,3>, <3,4,5>, <5,0,1>}
V3("Mean vec", Mean(AV))
GetStats(A)
#for (I,0,4) S("Stats", StatisticsArray[I]) #end
#declare H = array[10] {0, 1, 1.5, 2, 3, 3, 4, 9, 10, 5}

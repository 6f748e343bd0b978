// stdlib-meshmaker.pov: the meshes of meshmaker.inc (Lathe, Prism1,
// Coons, TwoVarSurf, Parametric, MSM) through their extents, points found
// with trace() and, for Lathe, Prism1 and Coons, the smooth normals there
// (turned to face the ray: POV-Ray's trace() does not turn a mesh's
// normals, lucent's does); the helpers' results; and the progress report
// the builders print. The normals of TwoVarSurf, Parametric and MSM are
// not printed: lucent's come from the grid by central differences, POV-Ray's
// differ (doc/stdlib.md).
#version 3.7;
#include "meshmaker.inc"
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ",", 0, 4) #end
#macro E(Name, O) #debug concat(Name, ": ", Str3(min_extent(O)), " / ", Str3(max_extent(O)), "\n") #end
#macro T(O, P, D) #local N = <0,0,0>; #local H = trace(O, P, D, N); #debug concat("  ", Str3(H), "\n") #end
#macro TN(O, P, D) #local N = <0,0,0>; #local H = trace(O, P, D, N);
	#if (vdot(N, D) > 0) #local N = -N; #end
	#debug concat("  ", Str3(H), " n ", Str3(N), "\n") #end
#declare S = spline { cubic_spline -0.5, <0.2, -0.5, 0>, 0, <0.5, 0, 0>, 0.5, <1, 0.5, 0>, 1, <0.5, 1, 0>, 1.5, <0.2, 1.5, 0> }
#declare L = Lathe(S, 4, 270, 6, "")
E("Lathe", L)
TN(L, <0, 0.5, -5>, z)
TN(L, <-5, 0.3, 0.1>, x)
TN(L, <5, 0.6, 0.3>, -x)
TN(L, <0.1, 0.7, 5>, -z)
#declare L = Lathe(S, 2, 360, 3, "")
E("Lathe2", L)
TN(L, <0, 0.5, -5>, z)
TN(L, <-5, 0.3, 0.1>, x)
TN(L, <5, 0.6, 0.3>, -x)
TN(L, <0.2, 0.25, -5>, z)
#declare S = spline { linear_spline -0.25, <0, 0, -1>, 0, <1, 0, 0>, 0.25, <0, 0, 1>, 0.5, <-1, 0, 0>, 0.75, <0, 0, -1>, 1, <1, 0, 0>, 1.25, <0, 0, 1> }
#declare P = spline { linear_spline -0.5, <1, -1, 0>, 0, <1, 0, 0>, 1, <0.5, 2, 0>, 1.5, <0.2, 3, 0> }
#declare O = Prism1(S, 4, P, 2, "")
E("Prism1", O)
TN(O, <0.1, 0.5, -5>, z)
TN(O, <0.1, 1.5, -5>, z)
TN(O, <-5, 1.2, 0.2>, x)
#declare S1 = spline { linear_spline 0, <0,0,0>, 1, <1,0,0> }
#declare S2 = spline { linear_spline 0, <1,0,0>, 1, <1,0,1> }
#declare S3 = spline { linear_spline 0, <1,0,1>, 1, <0,1,1> }
#declare S4 = spline { linear_spline 0, <0,1,1>, 1, <0,0,0> }
#declare O = Coons(S1, S2, S3, S4, 2, 3, "")
E("Coons", O)
TN(O, <0.5, 5, 0.5>, -y)
TN(O, <0.3, 5, 0.7>, -y)
TN(O, <0.8, 5, 0.2>, -y)
#declare F = function(u, v) { u*u - v }
#declare O = TwoVarSurf(F, <-1, 1>, <0, 2>, 3, 2, "")
E("TwoVarSurf", O)
T(O, <0.3, 0.7, -5>, z)
T(O, <-0.6, 1.3, -5>, z)
T(O, <0.9, 0.2, 5>, -z)
#declare F1 = function(u, v) { cos(u) * (1 + 0.3*cos(v)) }
#declare F2 = function(u, v) { 0.3*sin(v) }
#declare F3 = function(u, v) { sin(u) * (1 + 0.3*cos(v)) }
#declare O = Parametric(F1, F2, F3, <0, 0>, <2*pi, 2*pi>, 6, 4, "")
E("Parametric", O)
T(O, <0.1, 5, -1.1>, -y)
T(O, <-5, 0.1, 0.2>, x)
#declare A = array[5] {
  spline { linear_spline -1, <0,0,0>, 0, <0,0,0>, 1, <1,0,0>, 2, <2,0,0> },
  spline { linear_spline -1, <0,1,0>, 0, <0,1,0>, 1, <1,1,0>, 2, <2,1,0> },
  spline { linear_spline -1, <0,2,0>, 0, <0,2,0.5>, 1, <1,2,0>, 2, <2,2,0> },
  spline { linear_spline -1, <0,3,0>, 0, <0,3,0>, 1, <1,3,0>, 2, <2,3,0> },
  spline { linear_spline -1, <0,4,0>, 0, <0,4,0>, 1, <1,4,0>, 2, <2,4,0> } }
#declare O = MSM(A, 2, "l", 4, "")
E("MSM l", O)
#for (Y, 1, 3, 0.5) T(O, <0.3, Y + 0.13, -5>, z) #end
#declare O = MSM(A, 2, "c", 4, "")
E("MSM c", O)
#for (Y, 1, 3, 0.5) T(O, <0.3, Y + 0.13, -5>, z) #end
#declare Arr = array[5] { <0, 0>, <1, 1>, <2, 4>, <3, 9>, <4, 16> }
#declare Sp = BuildSpline(Arr, "q")
#debug concat("BuildSpline ", vstr(2, Sp(0), ",", 0, 4), " ", vstr(2, Sp(0.5), ",", 0, 4), " ", vstr(2, Sp(0.25), ",", 0, 4), "\n")
#declare Sp = BuildSpline(Arr, "c")
#debug concat("BuildSpline ", vstr(2, Sp(0), ",", 0, 4), " ", vstr(2, Sp(0.5), ",", 0, 4), " ", vstr(2, Sp(0.25), ",", 0, 4), "\n")
#debug concat("LInterpolate ", str(LInterpolate(0.25, 2, 4),0,4), " ", vstr(3, LInterpolate(0.5, <0,0,0>, <2,4,6>), ",", 0, 4), "\n")
#debug concat("RangeMM ", str(RangeMM(5, 0, 10, -1, 1),0,4), " ", str(RangeMM(2.5, 0, 10, 0, 100),0,4), "\n")
#debug concat("CheckFileName ", str(CheckFileName(""),0,0), str(CheckFileName("nonexistent.inc"),0,0), "\n")

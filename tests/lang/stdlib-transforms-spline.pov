// transforms.inc: Spline_Trans on linear and cubic splines: level and
// climbing turns, banking, foresight, a tilted sky, the ends of a spline
// (where POV-Ray normalizes zero vectors), and on an object. The bounding
// box prints with 5 decimals: POV-Ray keeps it in single precision.
#version 3.7;
#include "transforms.inc"
#macro V3(N, V) #debug concat(N, " ", vstr(3, V, ",", 0, 9), "\n") #end
#macro ShowT(N, T)
  V3(concat(N, " o"), vtransform(<0,0,0>, T))
  V3(concat(N, " x"), vtransform(<1,0,0>, T)-vtransform(<0,0,0>, T))
  V3(concat(N, " y"), vtransform(<0,1,0>, T)-vtransform(<0,0,0>, T))
  V3(concat(N, " z"), vtransform(<0,0,1>, T)-vtransform(<0,0,0>, T))
#end
#declare S1 = spline { linear_spline 0, <0,0,0> 1, <1,0,0> 2, <1,0,1> 3, <2,1,1> }
ShowT("lin 0.5 nobank", transform { Spline_Trans(S1, 0.5, y, 0.1, 0) })
ShowT("lin 0.5 bank", transform { Spline_Trans(S1, 0.5, y, 0.1, 1) })
ShowT("lin 0.95 nobank", transform { Spline_Trans(S1, 0.95, y, 0.1, 0) })
ShowT("lin 0.95 bank", transform { Spline_Trans(S1, 0.95, y, 0.1, 1) })
ShowT("lin 0.95 bank2", transform { Spline_Trans(S1, 0.95, y, 0.1, 2) })
ShowT("lin 0.95 bank fs0.2", transform { Spline_Trans(S1, 0.95, y, 0.2, 1) })
ShowT("lin 2.5 nobank", transform { Spline_Trans(S1, 2.5, y, 0.1, 0) })
ShowT("lin 2.5 sky z", transform { Spline_Trans(S1, 2.5, z, 0.1, 0) })
#declare S2 = spline { linear_spline 0, <0,0,0> 1, <1,0.5,0> 2, <1,1,1> 3, <0,1.5,1.5> }
ShowT("climb turn", transform { Spline_Trans(S2, 0.95, y, 0.1, 1) })
ShowT("climb turn right", transform { Spline_Trans(S2, 1.97, y, 0.05, 0.7) })
ShowT("climb turn sky", transform { Spline_Trans(S2, 0.97, <0.2,1,0.1>, 0.1, 1.5) })
#declare S3 = spline { cubic_spline -1, <-1,0,0> 0, <0,0,0> 1, <1,0.3,1> 2, <0,0.6,2> 3, <-1,0,1> 4, <0,0,0> }
#for (T, 0, 3, 0.375)
ShowT(concat("cubic ", str(T,0,3)), transform { Spline_Trans(S3, T, y, 0.05, 0.5) })
#end
#declare Obj = box { <-1,-1,-1>, <1,1,1> Spline_Trans(S3, 1.5, y, 0.1, 1) }
#debug concat("box min ", vstr(3, min_extent(Obj), ",", 0, 5), "\n")
#debug concat("box max ", vstr(3, max_extent(Obj), ",", 0, 5), "\n")

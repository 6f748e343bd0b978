// transforms.inc: each transformation macro, applied with vtransform and
// vinv_transform to the origin, the axes and a point.
#version 3.7;
#include "transforms.inc"
#macro V3(N, V) #debug concat(N, " ", vstr(3, V, ",", 0, 9), "\n") #end
#macro ShowT(N, T)
  V3(concat(N, " o"), vtransform(<0,0,0>, T))
  V3(concat(N, " x"), vtransform(<1,0,0>, T))
  V3(concat(N, " y"), vtransform(<0,1,0>, T))
  V3(concat(N, " z"), vtransform(<0,0,1>, T))
  V3(concat(N, " p"), vtransform(<0.3,-0.7,1.9>, T))
  V3(concat(N, " inv p"), vinv_transform(<0.3,-0.7,1.9>, T))
#end
ShowT("Shear", transform { Shear_Trans(<1,0.5,0>, <0,1,0.25>, <0.1,0.2,2>) })
ShowT("Matrix", transform { Matrix_Trans(<1,0.5,0>, <0,1,0.25>, <0.1,0.2,2>, <3,4,5>) })
ShowT("Axial", transform { Axial_Scale_Trans(<1,1,0>, 3) })
ShowT("AxialNeg", transform { Axial_Scale_Trans(<0,2,1>, 0.5) })
ShowT("AxisRot", transform { Axis_Rotate_Trans(<1,2,3>, 40) })
ShowT("RotAround", transform { Rotate_Around_Trans(<10,20,30>, <1,2,3>) })
ShowT("Reorient", transform { Reorient_Trans(<1,0,0>, <0,1,1>) })
ShowT("Reorient2", transform { Reorient_Trans(<1,2,3>, <-2,0.5,1>) })
ShowT("ReorientSame", transform { Reorient_Trans(<1,2,3>, <2,4,6>) })
ShowT("ReorientOpp", transform { Reorient_Trans(<1,0,0>, <-1,0,0>) })
ShowT("ReorientOpp2", transform { Reorient_Trans(<0,1,0>, <0,-2,0>) })
ShowT("ReorientOpp3", transform { Reorient_Trans(<1,2,3>, <-1,-2,-3>) })
ShowT("PointAt", transform { Point_At_Trans(<1,1,0>) })
ShowT("PointAt2", transform { Point_At_Trans(<0.3,-2,0.5>) })
ShowT("PointAtY", transform { Point_At_Trans(<0,3,0>) })
ShowT("PointAtNY", transform { Point_At_Trans(<0,-3,0>) })
#declare B = box { <1,2,3>, <4,7,5> }
ShowT("CenterX", transform { Center_Trans(B, x) })
ShowT("CenterXYZ", transform { Center_Trans(B, x+y+z) })
ShowT("Align", transform { Align_Trans(B, x, <10,10,10>) })
ShowT("Align2", transform { Align_Trans(B, <-1,1,0>, <10,10,10>) })
ShowT("Align3", transform { Align_Trans(B, -z, <0,0,0>) })

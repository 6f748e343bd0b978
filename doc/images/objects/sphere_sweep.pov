// sphere_sweep.pov: the same six spheres swept by linear_spline (red),
// b_spline (green) and cubic_spline (blue).
#version 3.7;
#declare Stage_From = <0, 3.5, -6.5>;
#declare Stage_At = <0, 0.9, 0.3>;
#include "stage.inc"

#declare Spheres = array[6] { <-0.8, 0, 0>, <-0.4, 1.2, 0>, <0, 0.2, 0.3>, <0.4, 1.4, -0.2>, <0.8, 0.3, 0>, <0.9, 1, 0.4> }
#declare Radii = array[6] { 0.15, 0.25, 0.35, 0.15, 0.3, 0.2 }
sphere_sweep { linear_spline 6, #for (i, 0, 5) Spheres[i], Radii[i] #end
  texture { T_Red } translate <-2.2, 0.3, 0.6> }
sphere_sweep { b_spline 6, #for (i, 0, 5) Spheres[i], Radii[i] #end
  texture { T_Green } translate <0, 0.3, 0.6> }
sphere_sweep { cubic_spline 6, #for (i, 0, 5) Spheres[i], Radii[i] #end
  texture { T_Blue } translate <2.2, 0.3, 0.6> }

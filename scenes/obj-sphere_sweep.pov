// obj-sphere_sweep.pov: sphere sweeps: a linear_spline zigzag of spheres of
// changing radius, a b_spline and a cubic_spline through the same spheres,
// a cubic_spline cut by a box (CSG), and a scaled and rotated linear one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> right x*image_width/image_height look_at <0, 1, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
sphere_sweep { linear_spline 4, <-1, 0, 0>, 0.2, <-0.3, 1, 0>, 0.45, <0.4, 0, 0.3>, 0.25, <1, 1.2, -0.2>, 0.35
  pigment { color rgb <0.9, 0.2, 0.2> } finish { Shiny } translate <-2.6, 0.5, 1.6> }
#declare Pts = array[6] { <-1.2, 0, 0>, <-0.6, 1.2, 0>, <0, 0.2, 0.5>, <0.6, 1.4, -0.3>, <1.2, 0.3, 0>, <1.4, 1, 0.5> }
#declare Rad = array[6] { 0.2, 0.3, 0.5, 0.2, 0.4, 0.3 }
sphere_sweep { b_spline 6,
  #for (i, 0, 5) Pts[i], Rad[i] #end
  pigment { color rgb <0.2, 0.8, 0.3> } finish { Shiny } translate <0.2, 0.3, 2.6> }
sphere_sweep { cubic_spline 6,
  #for (i, 0, 5) Pts[i], Rad[i] #end
  tolerance 1e-4
  pigment { color rgb <0.2, 0.3, 0.9> } finish { Shiny } rotate y*40 translate <2.6, 0.3, 1.2> }
difference {
  sphere_sweep { cubic_spline 5, <-1, -0.5, 0>, 0.3, <-0.8, 0.5, 0>, 0.35, <0, 0.8, 0.2>, 0.5, <0.8, 0.4, 0>, 0.3, <1, -0.5, 0>, 0.3 }
  box { <-2, -2, -2>, <2, 2, 0.05> }
  pigment { color rgb <0.9, 0.7, 0.2> } finish { Shiny }
  rotate y*-20 translate <0, 0.4, -1.2>
}
sphere_sweep { linear_spline 3, <0, 0, 0>, 0.3, <0.8, 0.6, 0>, 0.15, <1.4, 0, 0.4>, 0.3
  pigment { color rgb <0.5, 0.2, 0.7> } finish { Shiny } scale <1, 1.5, 1> rotate z*20 translate <-2.7, 0.3, -1.4> }

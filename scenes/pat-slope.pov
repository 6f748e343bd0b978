// pat-slope.pov: the slope pattern on spheres: a direction, a direction
// with a range, a direction with altitude, and point_at (with a range).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -12> look_at <0, 0, 0> angle 32 }
#declare M = color_map { [0 rgb <0.1, 0.15, 0.4>] [0.5 rgb <0.8, 0.7, 0.5>] [1 rgb 1] }
#macro S(P, X, Y)
  sphere { 0, 1 pigment { P color_map { M } } finish { ambient 1 diffuse 0 } translate <X, Y, 0> }
#end
S(pigment { slope { y } }, -2.2, 1.1)
S(pigment { slope { <1, 2, 0>, 0.3, 0.8 } }, 0, 1.1)
S(pigment { slope { <0, -1, 0> altitude <0, 2, 1>, -1, 1 } }, 2.2, 1.1)
S(pigment { slope { point_at <0, 3, -2> } }, -2.2, -1.1)
S(pigment { slope { point_at <1, -2, -3>, 0.2, 0.9 } }, 0, -1.1)
S(pigment { slope { point_at <0.3, 0.2, -1.5> } translate <2.2, -1.1, 0> }, 2.2, -1.1)

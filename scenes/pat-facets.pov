// pat-facets.pov: the facets normal in both its forms: size (the normal
// snapped to a perturbed grid of normals: flat faces on the spheres,
// one tilt on a flat surface) and coords (the crackle cells of p / size,
// tilted by coords), with a bump size, transforms, turbulence and metrics, on
// spheres, a plane and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.4, -6> look_at <0, 0.9, 0> angle 55 }
light_source { <4, 8, -6> color rgb 1 }
light_source { <-6, 4, -5> color rgb 0.35 }
#declare F = finish { ambient 0.1 diffuse 0.75 phong 0.5 phong_size 40 };
#declare P = pigment { rgb <0.85, 0.8, 0.7> };
plane { y, 0 texture { pigment { rgb 0.6 } normal { facets coords 0.5 size 0.4 } finish { F } } }
#macro Ball(X, Z, N)
  sphere { <X, 0.7, Z>, 0.7 texture { pigment { P } normal { N } finish { F } } }
#end
Ball(-2.4, 0, normal { facets })
Ball(-0.8, 0, normal { facets size 0.3 })
Ball(0.8, 0, normal { facets 0.5 size 0.5 metric 1 rotate 30*z scale <1, 2, 1> })
Ball(2.4, 0, normal { facets coords 0.6 size 0.15 turbulence 0.3 })
box { <-3, 0, -0.1>, <3, 2.2, 0.1> translate <0, 0, 1.4>
      texture { pigment { P } normal { facets coords 1 size 0.2 metric 3 scale 1.5 translate 0.2 } finish { F } } }

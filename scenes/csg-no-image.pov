// csg-no-image.pov: which rays see no_image and no_reflection objects. A
// ray transmitted through a surface, refracted or not, sees what the ray
// that reached the surface saw, as in POV-Ray. Left: through a clear pane
// (no ior change) the no_image red ball stays hidden and the no_reflection
// green one shows. Middle: the same behind a glass pane of ior 1.5. Right:
// a mirror turns the view to the side, through another pane: the no_image
// ball shows (a reflected ray) and the no_reflection one does not.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right 6*x up 3*y }
background { color rgb <0.1, 0.1, 0.2> }
light_source { <0, 5, -10> color rgb 1 }
#declare Lit = finish { ambient 1 diffuse 0 }
#declare Pane = texture { pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { ambient 0.05 diffuse 0 } }
#macro Targets(P)
  sphere { P + <0, 0.7, 0>, 0.5 pigment { rgb <1, 0, 0> } finish { Lit } no_image }
  sphere { P - <0, 0.7, 0>, 0.5 pigment { rgb <0, 1, 0> } finish { Lit } no_reflection }
  sphere { P + <0.45, 0, 0.8>, 0.3 pigment { rgb <0.2, 0.4, 1> } finish { Lit } }
#end
box { <-2.8, -1.7, -1.05>, <-1.2, 1.7, -0.95> texture { Pane } }
Targets(<-2, 0, 2>)
box { <-0.8, -1.7, -1.05>, <0.8, 1.7, -0.95> texture { Pane } interior { ior 1.5 } }
Targets(<0, 0, 2>)
// the mirror turns view rays (+z) to +x, through a pane of ior 1.5
box { <-1, -1.7, -0.05>, <1, 1.7, 0.05> rotate -45*y translate <2, 0, 0>
  pigment { rgb 0 } finish { ambient 0 diffuse 0 reflection 1 } }
box { <3.45, -1.7, -1>, <3.55, 1.7, 1> texture { Pane } interior { ior 1.5 } }
Targets(<5, 0, 0>)

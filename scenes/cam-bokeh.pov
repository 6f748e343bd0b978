// cam-bokeh.pov: focal blur through a bokeh: out-of-focus lights take the
// shape of the bokeh pigment: a triangle with its point at pigment y = 0
// (POV-Ray puts pigment y = 0 at the top of the lens), 64 lens samples a
// pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.02, 0.02, 0.05> }
#declare Lamp = sphere { 0, 0.12 pigment { color rgb <1, 0.85, 0.5> } finish { ambient 1 diffuse 0 } }
#for (I, 0, 4)
  object { Lamp translate <-3 + 1.5 * I, 1.8 + 0.3 * mod(I, 2), 9> }
#end
sphere { <0, 0.8, 2>, 0.8 pigment { checker color rgb <1, 0.25, 0.1> color rgb <1, 0.95, 0.4> scale 0.25 } finish { ambient 0.3 } }
plane { y, 0 pigment { checker color rgb 0.3 color rgb 0.1 } finish { ambient 0.3 } }
light_source { <-10, 20, -10> color rgb 1 }
camera {
  location <0, 1.2, -3> look_at <0, 1, 2> angle 50
  aperture 1.2 focal_point <0, 0.8, 2> blur_samples 64, 64
  bokeh { pigment { object {
    intersection { plane { <-2, 1, 0>, 0 } plane { <2, 1, 0>, 0 translate x } plane { y, 0.9 } }
    color rgb 0 color rgb 1 } } }
}

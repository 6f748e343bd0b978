// finish-terms.pov: the finish block, term by term. A row of spheres lit
// by one light, each with one term changed from the default: ambient,
// diffuse, brilliance, phong with phong_size, specular with roughness,
// metallic on a phong highlight, emission, and a texture { pigment finish }
// combining several. The front row declares finishes and textures.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 }

#declare Base = rgb <0.8, 0.3, 0.2>;
#declare Shiny = finish { phong 0.9 phong_size 60 }
#declare Gold = texture {
  pigment { color rgb <0.9, 0.65, 0.2> }
  finish { ambient 0.05 diffuse 0.5 specular 0.8 roughness 0.02 metallic }
}

camera {
  location <0, 4.5, -11>
  right x*image_width/image_height
  look_at <0, 0.9, 0>
  angle 48
}

light_source { <-6, 10, -8> color rgb 1 }

background { color rgb <0.05, 0.05, 0.08> }

plane { y, 0 pigment { color rgb 0.6 } finish { diffuse 0.8 ambient 0.05 } }

// back row
sphere { <-3.3, 0.7, 1.5>, 0.7 pigment { color Base } finish { ambient 0.4 } }
sphere { <-1.1, 0.7, 1.5>, 0.7 pigment { color Base } finish { diffuse 1.0 ambient 0 } }
sphere { < 1.1, 0.7, 1.5>, 0.7 pigment { color Base } finish { brilliance 4 } }
sphere { < 3.3, 0.7, 1.5>, 0.7 pigment { color Base } finish { emission rgb <0.3, 0.3, 0> } }
// front row
sphere { <-3.3, 0.7, -1>, 0.7 pigment { color Base } finish { Shiny } }
sphere { <-1.1, 0.7, -1>, 0.7 pigment { color Base } finish { specular 0.7 roughness 0.01 } }
sphere { < 1.1, 0.7, -1>, 0.7 pigment { color Base } finish { phong 1 phong_size 20 metallic } }
sphere { < 3.3, 0.7, -1>, 0.7 texture { Gold } }

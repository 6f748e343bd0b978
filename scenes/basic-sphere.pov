// basic-sphere.pov: the smallest useful scene. Exercises a perspective
// camera (location, look_at, angle, right from image_width/image_height),
// one point light with hard shadows, a background colour, a plane, a sphere,
// solid rgb pigments and the default finish (ambient 0.1, diffuse 0.6).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -5>
  right x*image_width/image_height
  look_at <0, 0.8, 0>
  angle 45
}

light_source { <-5, 8, -6> color rgb 1 }

background { color rgb <0.25, 0.35, 0.55> }

plane { y, 0 pigment { color rgb <0.8, 0.78, 0.7> } }

sphere { <0, 1, 0>, 1 pigment { color rgb <0.85, 0.25, 0.1> } }

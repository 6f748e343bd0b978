// mirror.pov: mirror reflection. Exercises finish { reflection } as a
// float and as a colour, two facing mirrors bounded by max_trace_level,
// reflection of the background, no_reflection (an object seen directly but
// not in mirrors) and no_image (an object seen only in mirrors), metallic
// tinting of the highlight on a reflective surface.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }

camera {
  location <0.3, 2.2, -6>
  right x*image_width/image_height
  look_at <0, 1.2, 0>
  angle 55
}

light_source { <-4, 8, -6> color rgb 1 }

background { color rgb <0.35, 0.5, 0.75> }

plane { y, 0 pigment { color rgb <0.6, 0.55, 0.5> } }

// two facing mirrors
box { <-3.2, 0, -2>, <-3, 3, 3> pigment { color rgb 0.1 }
  finish { reflection 0.85 ambient 0 diffuse 0.1 } }
box { <3, 0, -2>, <3.2, 3, 3> pigment { color rgb 0.1 }
  finish { reflection rgb <0.6, 0.8, 0.6> ambient 0 diffuse 0.1 } }

sphere { <0, 1, 0.5>, 1 pigment { color rgb <0.7, 0.7, 0.75> }
  finish { ambient 0 diffuse 0.2 reflection 0.7 phong 0.8 phong_size 80 metallic } }
sphere { <-1.6, 0.45, -0.8>, 0.45 pigment { color rgb <0.9, 0.2, 0.1> } }
sphere { <1.6, 0.45, -0.8>, 0.45 pigment { color rgb <0.1, 0.3, 0.9> } }
// seen directly only
sphere { <-1, 0.3, -2.2>, 0.3 pigment { color rgb <1, 0.9, 0.1> } no_reflection }
// seen in mirrors only (behind the camera)
sphere { <0.5, 1.5, -8>, 0.6 pigment { color rgb <0.1, 0.9, 0.3> } no_image }

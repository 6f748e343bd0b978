// showcase.pov: the picture in the README. A mirror sphere on a softly
// reflective floor, ringed by glossy spheres and boxes, lit by a warm key
// light and a cool fill light. Exercises #declare of colours, finishes,
// textures and objects, object { Ident } with transforms, spheres, boxes
// (rotated and stacked), a plane, mirror reflection (float and colour)
// with max_trace_level, phong and specular highlights, metallic, two point
// lights with hard shadows, and a camera using the aspect-ratio idiom
// right x*image_width/image_height. Render at 800x600 for the README.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

// ---- colours
#declare C_Sky    = rgb <0.025, 0.045, 0.11>;
#declare C_Floor  = rgb <0.16, 0.15, 0.15>;
#declare C_Red    = rgb <0.85, 0.12, 0.10>;
#declare C_Orange = rgb <0.95, 0.45, 0.08>;
#declare C_Yellow = rgb <0.95, 0.80, 0.15>;
#declare C_Green  = rgb <0.20, 0.70, 0.25>;
#declare C_Teal   = rgb <0.08, 0.60, 0.65>;
#declare C_Blue   = rgb <0.12, 0.30, 0.85>;
#declare C_Violet = rgb <0.55, 0.20, 0.80>;
#declare C_Ivory  = rgb <0.92, 0.88, 0.80>;

// ---- finishes and textures
#declare F_Gloss = finish { ambient 0.08 diffuse 0.7 phong 0.8 phong_size 90 }
#declare F_Satin = finish { ambient 0.08 diffuse 0.75 specular 0.35 roughness 0.03 }
#declare T_Chrome = texture {
  pigment { color rgb <0.75, 0.78, 0.82> }
  finish { ambient 0 diffuse 0.08 reflection 0.85 phong 1 phong_size 200 metallic }
}
#declare T_Gold = texture {
  pigment { color rgb <0.95, 0.70, 0.30> }
  finish { ambient 0.03 diffuse 0.5 reflection rgb <0.8, 0.6, 0.25>
           specular 0.9 roughness 0.008 metallic }
}

// ---- objects
#declare Ball  = sphere { <0, 0.45, 0>, 0.45 }
#declare Cube  = box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> }

camera {
  location <1.2, 3.4, -9.5>
  right x*image_width/image_height
  look_at <0, 0.9, 0.6>
  angle 44
}

light_source { <-7, 10, -8> color rgb <1.0, 0.94, 0.84> }
light_source { <8, 5, -4> color rgb <0.30, 0.36, 0.50> }

background { color C_Sky }

plane { y, 0
  pigment { color C_Floor }
  finish { ambient 0.05 diffuse 0.9 reflection 0.3 }
}

// the centrepiece
sphere { <0, 1.3, 0.6>, 1.3 texture { T_Chrome } }

// a ring of glossy balls around it
object { Ball translate <-2.58, 0, -0.34> pigment { color C_Red } finish { F_Gloss } }
object { Ball translate <-1.94, 0, -1.34> pigment { color C_Orange } finish { F_Gloss } }
object { Ball translate <-0.94, 0, -1.98> pigment { color C_Yellow } finish { F_Gloss } }
object { Ball translate <0.24, 0, -2.14> pigment { color C_Green } finish { F_Gloss } }
object { Ball translate <1.38, 0, -1.78> pigment { color C_Teal } finish { F_Gloss } }
object { Ball translate <2.25, 0, -0.98> pigment { color C_Blue } finish { F_Gloss } }
object { Ball translate <2.71, 0, 0.12> pigment { color C_Violet } finish { F_Gloss } }

// a gold ball on a stack of boxes, back left
object { Cube scale <1.4, 0.7, 1.4> rotate y*20 translate <-2.8, 0, 2.6>
  pigment { color C_Ivory } finish { F_Satin } }
object { Cube scale <0.9, 0.6, 0.9> rotate y*-10 translate <-2.8, 0.7, 2.6>
  pigment { color C_Teal } finish { F_Satin } }
sphere { <-2.8, 1.85, 2.6>, 0.55 texture { T_Gold } }

// a pillar and a cube balanced on an edge, back right
object { Cube scale <0.6, 2.6, 0.6> rotate y*30 translate <3.2, 0, 2.8>
  pigment { color C_Red } finish { F_Satin } }
object { Cube scale 0.8 translate <0, -0.4, 0> rotate z*45 rotate y*-30 translate <1.9, 0.566, 1.9>
  pigment { color C_Yellow } finish { F_Satin } }
sphere { <3.6, 0.3, 1.2>, 0.3 pigment { color C_Ivory } finish { F_Gloss } }

// transforms.pov: object transformations and their order. Exercises
// translate, rotate (about one and several axes), uniform and non-uniform
// scale (an ellipsoid and a flattened box), negative scale (mirroring), a
// shear made by rotating then scaling unevenly, a full matrix (another
// shear), transforms on #declare'd objects applied again at use, the order
// of scale and rotate, and normals after non-uniform scaling (seen in the
// highlights).
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Cube = box { -0.5, 0.5 }
#declare Hi = finish { phong 0.7 phong_size 50 }

camera {
  location <0, 3.5, -9>
  right x*image_width/image_height
  look_at <-0.6, 0.9, 0.3>
  angle 50
}

light_source { <-5, 10, -10> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.35 }

background { color rgb <0.12, 0.12, 0.2> }

plane { y, 0 pigment { color rgb <0.75, 0.7, 0.65> } }

// ellipsoid: non-uniform scale, then rotate, then translate
sphere { 0, 1 scale <1.2, 0.5, 0.5> rotate z*30 translate <-3, 1.2, 0>
  pigment { color rgb <0.9, 0.3, 0.3> } finish { Hi } }
// the same two operations in the other order
sphere { 0, 1 rotate z*30 scale <1.2, 0.5, 0.5> translate <-3, 0.5, -1.8>
  pigment { color rgb <0.3, 0.9, 0.4> } finish { Hi } }
// cube standing on a corner: rotations about x then z
object { Cube rotate <45, 0, 35.264> scale 1.1 translate <0, 1, 0>
  pigment { color rgb <0.3, 0.5, 0.95> } finish { Hi } }
// flattened, rotated box
object { Cube scale <2, 0.2, 1> rotate y*-30 translate <2.6, 0.1, 1>
  pigment { color rgb <0.95, 0.8, 0.3> } }
// sheared prism: a rotation followed by a non-uniform scale
object { Cube rotate z*45 scale <0.8, 1.6, 0.8> translate <2.4, 1.13, 1.6>
  pigment { color rgb <0.8, 0.4, 0.9> } finish { Hi } }
// sheared column given as a matrix: x += 0.4*y
object { Cube scale <0.5, 1.8, 0.5> translate <0, 0.9, 0>
  matrix < 1,   0, 0,
           0.4, 1, 0,
           0,   0, 1,
           0,   0, 0 >
  translate <0.9, 0, 2.6>
  pigment { color rgb <0.95, 0.55, 0.25> } finish { Hi } }
// mirrored by a negative scale: must look like a plain sphere
sphere { <1, 0, 0>, 0.5 scale <-1, 1, 1> translate <2.2, 0.5, -1.6>
  pigment { color rgb <0.4, 0.9, 0.9> } finish { Hi } }

// mesh-flat-normals.pov: mesh faces whose three normals are equal are shaded
// flat with the face normal, as in POV-Ray, even where those normals lean
// away from it (left and right faces) or point along the face (the floor one).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,1,-4> look_at <0,0.5,0> angle 50 }
light_source { <-3,5,-6> rgb 1 }
mesh {
  smooth_triangle { <-1.5,0,0>, <0,0.6,-0.8>, <0,0,0>, <0,0.6,-0.8>, <-0.75,1.5,0>, <0,0.6,-0.8> }
  smooth_triangle { <0,0,0>, <0.5,0.3,-0.8>, <1.5,0,0>, <0.5,0.3,-0.8>, <0.75,1.5,0>, <0.5,0.3,-0.8> }
  smooth_triangle { <-1,0,-0.5>, <0,1,0>, <1,0,-0.5>, <0,1,0>, <0,0,-1.5>, <0,1,0> }
  pigment { rgb <0.9,0.7,0.3> } finish { phong 0.5 }
}
plane { y, -0.01 pigment { checker rgb 0.8 rgb 0.5 } }

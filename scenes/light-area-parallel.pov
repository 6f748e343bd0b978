// Parallel and cylinder area lights: each point of the grid is a light of
// its own running toward point_at, so the penumbra is the grid's size seen
// from point_at; fading measures the distance to the light's plane. The
// cylinder light also has area_illumination.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
sphere { <-1.2,0.8,0>, 0.8 pigment { rgb <1,0.9,0.7> } finish { Mat } }
box { <0.5,0.01,-0.4>, <1.5,1.6,0.4> rotate y*25 pigment { rgb <0.7,0.8,1> } finish { Mat } }
cylinder { <0,0.01,1.5>, <0,2.2,1.5>, 0.15 pigment { rgb 1 } finish { Mat } }
light_source { <-2,4,-1>, rgb 0.7 parallel point_at <-0.5,0,0.5>
  area_light <1.5,0,0>, <0,0,1.5>, 5, 5 fade_distance 3 fade_power 2 }
light_source { <2,3,-2>, rgb <1,0.8,0.6> cylinder radius 1.2 falloff 2 point_at <1,0,0.5>
  area_light <1,0,0>, <0,0,1>, 4, 4 area_illumination }

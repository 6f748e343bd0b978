// area_illumination: the diffuse and highlights of two area lights are the
// mean over their grids (each point lighting from its own direction), not
// the light at their centres: a wide rectangular light and an area
// spotlight whose cone moves with each point of its grid.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 specular 0.3 roughness 0.02 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 }
sphere { <-1.2,0.8,0>, 0.8 pigment { rgb <1,0.9,0.7> } finish { Mat } }
box { <0.5,0.01,-0.4>, <1.5,1.6,0.4> rotate y*25 pigment { rgb <0.7,0.8,1> } finish { Mat } }
cylinder { <0,0.01,1.5>, <0,2.2,1.5>, 0.15 pigment { rgb 1 } finish { Mat } }
light_source { <-0.5,2.5,-1.6>, rgb 0.8
  area_light <5,0,0>, <0,0,1.5>, 7, 3 area_illumination }
light_source { <2,3,-1>, rgb <1,0.7,0.4>
  spotlight radius 10 falloff 22 point_at <1.5,0,0>
  area_light <2,0,0>, <0,0,2>, 4, 4 adaptive 1 area_illumination on fade_distance 3 fade_power 1 }

// expect: 2:45: roughness must be greater than 0
sphere { 0, 1 finish { specular 1 roughness 0 } }

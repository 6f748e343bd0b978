// expect: 2:50: falloff must be greater than 0
sphere { 0, 1 finish { reflection { 0, 1 falloff -1 } } }

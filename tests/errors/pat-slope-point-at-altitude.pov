// expect: 4:52: 'altitude' cannot be used with 'point_at' in the slope pattern
// POV-Ray: "Keyword 'altitude' cannot be used with 'point_at' in slope pattern."
#version 3.7;
sphere { 0, 1 pigment { slope { point_at <0, 3, 0> altitude y } } }

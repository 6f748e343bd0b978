// expect: 3:55: radius needs spotlight or cylinder before it
#version 3.7;
union { sphere { 0, 1 } light_source { <0,3,0>, rgb 1 radius 5 } }

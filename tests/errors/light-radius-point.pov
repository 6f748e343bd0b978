// expect: 3:31: radius needs spotlight or cylinder before it
#version 3.7;
light_source { <0,5,0>, rgb 1 radius 10 spotlight }

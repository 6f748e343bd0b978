// expect: 3:31: point_at needs spotlight or cylinder before it (or parallel)
#version 3.7;
light_source { <0,5,0>, rgb 1 point_at 0 parallel }

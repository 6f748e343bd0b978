// expect: 3:16: fog_type must be 1 (constant fog) or 2 (ground fog), not 3
#version 3.7;
fog { fog_type 3 distance 5 color rgb 1 }

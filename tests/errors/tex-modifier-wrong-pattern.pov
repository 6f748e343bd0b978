// expect: 3:29: 'mortar' can only be used with the brick pattern
#version 3.7;
#declare P = pigment { bozo mortar 0.2 }

// expect: 3:36: expected a warp type (repeat, black_hole, turbulence, cylindrical, spherical, toroidal, planar or cubic), found 'sphere'
#version 3.7;
#declare P = pigment { bozo warp { sphere } }

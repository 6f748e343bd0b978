// checks vnormalize on axis and general vectors
#version 3.7;
#debug concat(vstr(3, vnormalize(<3,0,0>), ",", 0, 6), "\n")
#debug concat(vstr(3, vnormalize(<3,4,0>), ",", 0, 6), "\n")
#debug concat(vstr(3, vnormalize(<1,1,1>), ",", 0, 6), "\n")
#debug concat(vstr(3, vnormalize(<-2,1,-2>), ",", 0, 6), "\n")
#debug concat(str(vlength(vnormalize(<7,-3,11>)), 0, 6), "\n")

// checks vector functions applied to 2-D and 4-D vectors (promoted to 3-D)
#version 3.7;
#debug concat(str(vlength(<3,4>), 0, 6), "\n")
#debug concat(vstr(3, vnormalize(<3,4>), ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(<1,0>, <0,1>), ",", 0, 6), "\n")

// checks vcross, including anti-commutativity and parallel vectors
#version 3.7;
#debug concat(vstr(3, vcross(x, y), ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(y, x), ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(<1,2,3>, <4,5,6>), ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(<1,2,3>, <2,4,6>), ",", 0, 6), "\n")
#debug concat(str(vlength(vcross(<2,0,0>, <0,3,0>)), 0, 6), "\n")

// checks vstr() examples from the manual: dimension count, separators, padding
#version 3.7;
#debug concat(vstr(2, <1,2>, ", ", 0,1), "\n")
#debug concat(vstr(5, <1,2,3,4,5>, ", ", 0,1), "\n")
#debug concat(vstr(3, <1,2>, ", ", 0,1), "\n")
#debug concat(vstr(5, <1,2,3>, ", ", 0,1), "\n")
#debug concat(vstr(4, <1,2,3,4>, "", 0,0), "\n")
#debug concat(vstr(3, <-1.5,2.25,3>, " / ", 0,3), "\n")

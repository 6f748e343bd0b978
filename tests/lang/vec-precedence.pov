// checks operator precedence in vector expressions
#version 3.7;
#debug concat(vstr(3, x+y*2, ",", 0, 6), "\n")
#debug concat(vstr(3, (x+y)*2, ",", 0, 6), "\n")
#debug concat(vstr(3, <1,2,3>*<2,2,2>-<1,1,1>/2, ",", 0, 6), "\n")
#debug concat(vstr(3, -<1,2,3>*2, ",", 0, 6), "\n")
#debug concat(vstr(3, 1-x-y, ",", 0, 6), "\n")

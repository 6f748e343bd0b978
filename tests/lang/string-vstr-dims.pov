// checks vstr() clipping of the dimension count to 2..5
#version 3.7;
#debug concat(vstr(1, <1,2>, ",", 0, 1), "\n")
#debug concat(vstr(0, <1,2>, ",", 0, 1), "\n")
#debug concat(vstr(7, <1,2,3,4,5>, ",", 0, 1), "\n")
#debug concat(vstr(3.9, <1,2,3>, ",", 0, 1), "\n")

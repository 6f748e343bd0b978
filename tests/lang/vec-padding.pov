// checks padding of lower-dimension vectors with zeros when mixed with higher ones
#version 3.7;
#declare V2 = <7,6>;
#declare V3 = <1,2,3>;
#debug concat(vstr(4, V2, ",", 0, 6), "\n")
#debug concat(vstr(5, V3, ",", 0, 6), "\n")
#debug concat(vstr(3, V2 + V3, ",", 0, 6), "\n")
#debug concat(vstr(3, V3 + V2, ",", 0, 6), "\n")
#debug concat(vstr(4, V2 + <1,1,1,1>, ",", 0, 6), "\n")
#debug concat(vstr(3, V2 * V3, ",", 0, 6), "\n")

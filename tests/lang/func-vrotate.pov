// checks vrotate (x then y then z rotation, degrees, left-handed)
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#debug concat(V3(vrotate(x, <0,0,90>)), "\n")
#debug concat(V3(vrotate(x, <0,90,0>)), "\n")
#debug concat(V3(vrotate(y, <90,0,0>)), "\n")
#debug concat(V3(vrotate(<1,2,3>, <30,45,60>)), "\n")
#debug concat(V3(vrotate(<1,0,0>, <0,45,0>)), "\n")
#debug concat(V3(vrotate(<1,1,1>, <10,-20,30>)), "\n")
#debug concat(V3(vrotate(<0,0,5>, 90*x)), "\n")

// checks vaxis_rotate about axis vectors and an arbitrary axis
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#debug concat(V3(vaxis_rotate(x, z, 90)), "\n")
#debug concat(V3(vaxis_rotate(x, y, 90)), "\n")
#debug concat(V3(vaxis_rotate(<1,2,3>, <1,1,1>, 120)), "\n")
#debug concat(V3(vaxis_rotate(<1,0,0>, <0,0,2>, 45)), "\n")
#debug concat(V3(vaxis_rotate(<1,2,3>, <1,-2,0.5>, 33)), "\n")

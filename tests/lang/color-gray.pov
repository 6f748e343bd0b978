// checks .gray weights (0.297 red, 0.589 green, 0.114 blue) on several colours
#version 3.7;
#macro G(C) #debug concat(str(C.gray, 0, 6), "\n") #end
G(rgb <1,0,0>)
G(rgb <0,1,0>)
G(rgb <0,0,1>)
G(rgb 1)
G(rgb <0.2,0.4,0.6>)
G(rgbft <0.5,0.5,0.5,1,1>)
#declare V = <1,2,3>;
#debug concat(str(V.gray, 0, 6), "\n")

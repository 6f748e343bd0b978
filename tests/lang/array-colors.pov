// checks an array of colours
#version 3.7;
#declare FlagColors = array[3] {rgb <1,0,0>, rgb <1,1,1>, rgbt <0,0,1,0.5>};
#for (I, 0, 2) #debug concat(vstr(5, FlagColors[I], ",", 0, 1), "\n") #end
#debug concat(str(FlagColors[2].transmit, 0, 2), "\n")

// checks #for with fractional start and end values
#version 3.7;
#for (I, 0.5, 3.2)
  #debug concat(str(I, 0, 2), " ")
#end
#debug concat("| after ", str(I, 0, 2), "\n")
#for (I, -1.5, -3.9, -1)
  #debug concat(str(I, 0, 2), " ")
#end
#debug concat("| after ", str(I, 0, 2), "\n")

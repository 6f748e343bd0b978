// checks #for counting down with a negative step
#version 3.7;
#for (I, 5, 1, -1)
  #debug concat(str(I, 0, 0), " ")
#end
#debug concat("\nafter: ", str(I, 0, 6), "\n")
#for (J, 10, 0, -2.5)
  #debug concat(str(J, 0, 1), " ")
#end
#debug concat("\nafter: ", str(J, 0, 6), "\n")

// checks #for with a positive step that does not land on End
#version 3.7;
#for (I, 0, 330, 30)
  #debug concat(str(I, 0, 0), " ")
#end
#debug concat("\nafter: ", str(I, 0, 6), "\n")
#for (J, 0, 10, 3)
  #debug concat(str(J, 0, 0), " ")
#end
#debug concat("\nafter: ", str(J, 0, 6), "\n")

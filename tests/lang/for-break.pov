// checks #break inside #for (the manual's example with a deterministic condition)
#version 3.7;
#for (I, 1, 100)
  #if (I * I > 20)
    #break
  #end
  #debug concat(str(I, 0, 0), " iterations and counting\n")
#end
#debug concat("after break I=", str(I, 0, 0), "\n")

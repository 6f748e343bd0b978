// checks writing a file of POV-Ray code and including it (a scene that writes its own include)
#version 3.7;
#fopen F "fileio-generated-include.tmp" write
#write (F, "#declare Gen_Array = array[4] {")
#for (I, 0, 3)
  #write (F, str(I * I, 0, 0))
  #if (I < 3) #write (F, ", ") #end
#end
#write (F, "}\n")
#write (F, "#macro Gen_Macro(X) (X + ", str(42, 0, 0), ") #end\n")
#fclose F
#include "fileio-generated-include.tmp"
#debug concat(str(Gen_Array[3], 0, 0), " ", str(Gen_Macro(8), 0, 0), "\n")

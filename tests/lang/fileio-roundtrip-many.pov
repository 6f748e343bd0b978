// checks writing 50 computed values separated by commas and reading them back exactly
#version 3.7;
#fopen F "fileio-roundtrip-many.tmp" write
#for (I, 1, 50)
  #write (F, str(sqrt(I), 0, 12))
  #if (I < 50) #write (F, ",") #end
  #if (mod(I, 10) = 0) #write (F, "\n") #end
#end
#fclose F
#fopen F "fileio-roundtrip-many.tmp" read
#declare MaxErr = 0;
#for (I, 1, 50)
  #read (F, V)
  #declare MaxErr = max(MaxErr, abs(V - sqrt(I)));
#end
#fclose F
#debug concat("max error below 1e-11: ", str((MaxErr < 1e-11), 0, 0), "\n")

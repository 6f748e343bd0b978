// checks chr() across the printable ASCII range
#version 3.7;
#declare S = "";
#for (I, 32, 126)
  #declare S = concat(S, chr(I));
  #if (mod(I - 31, 32) = 0) #debug concat(S, "\n") #declare S = ""; #end
#end
#debug concat(S, "\n")

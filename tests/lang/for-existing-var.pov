// checks a #for loop over an identifier that already exists (it is overwritten)
#version 3.7;
#declare I = "a string before the loop";
#for (I, 1, 2)
  #debug concat(str(I, 0, 0), "\n")
#end
#debug concat("I=", str(I, 0, 0), "\n")

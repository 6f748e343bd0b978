// checks str() building a table of padded numbers in a loop
#version 3.7;
#for (I, 1, 12, 1.5)
  #debug concat(str(I, 5, 1), "|", str(I*I, -8, 2), "|", str(-I, 7, 0), "\n")
#end

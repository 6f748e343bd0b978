// checks that a comma separates a vector from a following signed float
#version 3.7;
#macro Two(A, B) #debug concat(vstr(3, A, ",", 0, 6), " | ", str(B, 0, 6), "\n") #end
Two(<1,2,3>, -4)
Two(<1,2,3>-4, 1)
Two(x, -1)

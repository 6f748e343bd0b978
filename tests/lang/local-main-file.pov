// checks that #local in the main file acts like #declare (visible in macros and later)
#version 3.7;
#local A = 10;
#macro ShowA() #debug concat("A in macro=", str(A, 0, 0), "\n") #end
ShowA()
#local A = A + 1;
ShowA()
#declare A = A + 1;
#debug concat("A=", str(A, 0, 0), "\n")

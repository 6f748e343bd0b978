// checks macros used like functions returning a float expression
#version 3.7;
#macro Square(X) (X * X) #end
#macro Avg(A, B) ((A + B) / 2) #end
#debug concat(str(Square(7), 0, 6), " ", str(Avg(3, 8), 0, 6), "\n")
#debug concat(str(Square(Avg(2, 4)) + 1, 0, 6), "\n")
#declare Q = Square(1.5) * 2;
#debug concat(str(Q, 0, 6), "\n")

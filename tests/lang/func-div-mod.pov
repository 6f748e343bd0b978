// checks div() (truncating integer division) and mod() (remainder with the dividend's sign)
#version 3.7;
#macro Row(A, B) #debug concat(str(A, 0, 1), ",", str(B, 0, 1), ": div=", str(div(A, B), 0, 6), " mod=", str(mod(A, B), 0, 6), "\n") #end
Row(7, 2) Row(-7, 2) Row(7, -2) Row(-7, -2) Row(6, 3) Row(7.5, 2) Row(5.5, 1.5) Row(-5.5, 1.5) Row(1, 3) Row(0, 5)

// checks macro parameter lists and calls without commas, and with a trailing comma
#version 3.7;
#macro M(A B,)
#debug concat(str(A,0,0),"/",str(B,0,0),"\n")
#end
M(1 2)
M(3, 4,)
#macro Swap(A B) #local T = A; #declare A = B; #declare B = T; #end
#declare X = 1;
#declare Y = 2;
Swap(X Y)
#debug concat(str(X,0,0),"/",str(Y,0,0),"\n")

// checks a macro returning a vector expression
#version 3.7;
#macro Mid(A, B) ((A + B) / 2) #end
#macro Make(X, Y, Z) <X, Y, Z> #end
#debug concat(vstr(3, Mid(<0,0,0>, <2,4,6>), ",", 0, 6), "\n")
#debug concat(vstr(3, Make(1, 2, 3) * 2, ",", 0, 6), "\n")
#declare V = Make(9, 8, 7);
#debug concat(str(V.y, 0, 6), "\n")

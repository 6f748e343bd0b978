// checks float promotion through vector-valued macro arithmetic
#version 3.7;
#macro Lerp(A, B, T) (A + (B - A) * T) #end
#debug concat(vstr(3, Lerp(<0,0,0>, <10,20,30>, 0.25), ",", 0, 6), "\n")
#debug concat(str(Lerp(2, 4, 0.5), 0, 6), "\n")
#debug concat(vstr(3, Lerp(0, <2,4,6>, 0.5), ",", 0, 6), "\n")

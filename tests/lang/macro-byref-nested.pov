// checks a by-reference parameter passed on through a second macro
#version 3.7;
#macro Inner(P) #declare P = P * 2; #end
#macro Outer(Q) Inner(Q) #declare Q = Q + 1; #end
#declare N = 5;
Outer(N)
#debug concat("N=", str(N, 0, 0), "\n")

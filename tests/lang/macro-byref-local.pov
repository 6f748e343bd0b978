// checks that #local on a by-reference parameter does not write back
#version 3.7;
#macro SetLocal(V) #local V = 100; #debug concat("inside=", str(V, 0, 0), "\n") #end
#macro SetDeclare(V) #declare V = 200; #end
#declare A = 1;
SetLocal(A)
#debug concat("A after SetLocal=", str(A, 0, 0), "\n")
SetDeclare(A)
#debug concat("A after SetDeclare=", str(A, 0, 0), "\n")

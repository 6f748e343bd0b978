// checks macro calls inside array initialisers (3.7 needs each such item to start with another token, e.g. '(')
#version 3.7;
#macro Sq(X) (X * X) #end
#macro V(X) <X, X * 2, X * 3> #end
#declare A = array[4] {(Sq(1)), (Sq(2)), 0 + Sq(3), (Sq(4))};
#declare B = array[2] {(V(1)), (V(2))};
#debug concat(str(A[0] + A[1] + A[2] + A[3], 0, 0), " ", vstr(3, B[1], ",", 0, 0), "\n")

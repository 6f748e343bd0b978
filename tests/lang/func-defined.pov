// checks defined() on declared, undeclared and undefined identifiers
#version 3.7;
#declare A = 1;
#debug concat(str(defined(A), 0, 0), " ", str(defined(B), 0, 0), "\n")
#undef A
#debug concat(str(defined(A), 0, 0), "\n")
#declare S = "text";
#declare V = <1,2,3>;
#macro M() 1 #end
#debug concat(str(defined(S), 0, 0), str(defined(V), 0, 0), "\n")

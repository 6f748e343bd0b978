// checks macros calling other macros, including one defined after the caller
#version 3.7;
#macro Twice(X) (2 * X) #end
#macro Quad(X) Twice(Twice(X)) #end
#macro Later_User(X) Defined_Later(X) + 1 #end
#macro Defined_Later(X) (X * 100) #end
#debug concat(str(Quad(3), 0, 0), " ", str(Later_User(2), 0, 0), "\n")

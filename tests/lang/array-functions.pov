// checks an array of user-defined functions called by element
#version 3.7;
#declare F = array[3];
#declare F[0] = function(a) { a + 1 }
#declare F[1] = function(a) { a * a }
#declare F[2] = function(a) { -a }
#declare G = F[1];
#debug concat(str(G(7), 0, 0), "\n")

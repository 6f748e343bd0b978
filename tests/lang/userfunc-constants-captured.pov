// checks that identifiers used in a function body are captured when the function is declared
#version 3.7;
#declare C = 5;
#declare N = function { C * x }
#declare C = 6;
#debug concat(str(N(2, 0, 0), 0, 6), "\n")
#declare Vy = 2;
#declare Vz = 3;
#declare W = function(a) { a * Vy + Vz }
#declare Vy = 100;
#debug concat(str(W(10), 0, 6), "\n")

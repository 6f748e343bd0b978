// checks arithmetic, unary minus and precedence inside functions
#version 3.7;
#declare A = function(a, b) { a + b * 2 - a / b }
#declare B = function(a) { -a*a }
#declare C = function(a) { a - - a }
#declare D = function(a, b) { (a + b) * (a - b) }
#debug concat(str(A(4, 2), 0, 6), " ", str(B(3), 0, 6), " ", str(C(3), 0, 6), " ", str(D(5, 3), 0, 6), "\n")

// checks relational operators inside functions (no parentheses needed)
#version 3.7;
#declare L = function(a, b) { a < b }
#declare LE = function(a, b) { a <= b }
#declare E = function(a, b) { a = b }
#declare NE = function(a, b) { a != b }
#declare GE = function(a, b) { a >= b }
#declare G = function(a, b) { a > b }
#for (I, 1, 3)
  #debug concat(str(L(I, 2), 0, 0), str(LE(I, 2), 0, 0), str(E(I, 2), 0, 0), str(NE(I, 2), 0, 0), str(GE(I, 2), 0, 0), str(G(I, 2), 0, 0), "\n")
#end
#declare J = function(a) { 2 + a < 3 }
#debug concat(str(J(0), 0, 0), str(J(1), 0, 0), "\n")

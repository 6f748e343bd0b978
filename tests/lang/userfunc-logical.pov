// checks & and | inside functions, where & binds tighter than | (unlike outside functions)
#version 3.7;
#declare I = function(a) { a > 0 & a < 2 | a = 5 }
#debug concat(str(I(1), 0, 0), str(I(5), 0, 0), str(I(3), 0, 0), str(I(-1), 0, 0), "\n")
#declare P = function(a, b, c) { a | b & c }
#debug concat("fn 1|1&0=", str(P(1, 1, 0), 0, 0), "  expr 1|1&0=", str((1 | 1 & 0), 0, 0), "\n")
#declare Q = function(a, b) { a & b }
#debug concat(str(Q(2, 3), 0, 0), str(Q(0, 3), 0, 0), str(Q(0.5, -1), 0, 0), "\n")

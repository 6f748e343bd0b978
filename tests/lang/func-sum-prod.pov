// checks sum() and prod() inside user functions
#version 3.7;
#declare factorial = function(C) { prod(i, 1, C, i) }
#declare A = factorial(5);
#debug concat(str(A, 0, 6), "\n")
#declare Squares = function(n) { sum(i, 1, n, i*i) }
#debug concat(str(Squares(4), 0, 6), " ", str(Squares(10), 0, 6), "\n")
#declare Half = function(n) { sum(k, 0.5, n, k) }
#debug concat(str(Half(3), 0, 6), "\n")
#declare Empty = function(n) { sum(i, 5, n, i) + prod(j, 5, n, j) }
#debug concat(str(Empty(2), 0, 6), "\n")
#declare Nested = function(n) { sum(i, 1, n, prod(j, 1, i, 2)) }
#debug concat(str(Nested(4), 0, 6), "\n")

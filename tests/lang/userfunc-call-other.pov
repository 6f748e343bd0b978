// checks user functions calling other user functions
#version 3.7;
#declare Sq = function(a) { a * a }
#declare SumSq = function(a, b) { Sq(a) + Sq(b) }
#declare Hyp = function(a, b) { sqrt(SumSq(a, b)) }
#debug concat(str(Hyp(3, 4), 0, 6), " ", str(Hyp(5, 12), 0, 6), "\n")
#declare F3 = function { Sq(x) + Sq(y) + Sq(z) }
#debug concat(str(F3(1, 2, 3), 0, 6), "\n")

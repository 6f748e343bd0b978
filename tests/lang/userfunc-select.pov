// checks select() inside functions with three and four arguments
#version 3.7;
#declare S3 = function(a) { select(a, -1, 1) }
#declare S4 = function(a) { select(a, -1, 0, 1) }
#declare Abs = function(a) { select(a, -a, a) }
#for (A, -2, 2)
  #debug concat(str(S3(A), 0, 0), " ", str(S4(A), 0, 0), " ", str(Abs(A), 0, 0), "\n")
#end

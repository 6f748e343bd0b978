// checks #for with fractional steps, where rounding decides the last iteration
#version 3.7;
#for (I, 0, 1, 0.25)
  #debug concat(str(I, 0, 2), " ")
#end
#debug concat("\nafter: ", str(I, 0, 6), "\n")
#declare N = 0;
#for (J, 0, 1, 0.1)
  #declare N = N + 1;
#end
#debug concat("N=", str(N, 0, 0), " after: ", str(J, 0, 17), "\n")
#for (K, 0.5, 2)
  #debug concat(str(K, 0, 1), " ")
#end
#debug concat("\nafter: ", str(K, 0, 6), "\n")

// checks a #while loop with a fractional increment (accumulated rounding)
#version 3.7;
#declare T = 0;
#declare N = 0;
#while (T < 1)
  #declare N = N + 1;
  #declare T = T + 0.1;
#end
#debug concat("N=", str(N, 0, 0), " T=", str(T, 0, 17), "\n")
#declare Ctr = 0;
#declare K = 0;
#while (Ctr < 1)
  #declare Ctr = Ctr + 0.01;
  #declare K = K + 1;
#end
#debug concat("K=", str(K, 0, 0), "\n")

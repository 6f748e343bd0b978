// checks a small numeric program: Euclid's gcd and primes below 60 using #while and mod
#version 3.7;
#macro Gcd(A, B)
  #local P = A;
  #local Q = B;
  #while (Q != 0)
    #local T = mod(P, Q);
    #local P = Q;
    #local Q = T;
  #end
  P
#end
#debug concat(str(Gcd(1071, 462), 0, 0), " ", str(Gcd(17, 5), 0, 0), " ", str(Gcd(100, 75), 0, 0), "\n")
#for (N, 2, 60)
  #local Prime = 1;
  #local D = 2;
  #while (D * D <= N & Prime)
    #if (mod(N, D) = 0) #local Prime = 0; #end
    #local D = D + 1;
  #end
  #if (Prime) #debug concat(str(N, 0, 0), " ") #end
#end
#debug "\n"

// checks number tokens: leading/trailing dots, exponents, and numbers next to operators
#version 3.7;
#debug concat(str(1.e2, 0, 0), " ", str(.5e1, 0, 0), " ", str(2E-1, 0, 1), " ", str(1e+1, 0, 0), "\n")
#debug concat(str(1+2e1-3, 0, 0), " ", str(3*.5, 0, 1), " ", str(10/4., 0, 2), "\n")
#debug concat(str(000.5000, 0, 2), " ", str(1e0, 0, 0), " ", str(12345678901234567890, 0, 0), "\n")

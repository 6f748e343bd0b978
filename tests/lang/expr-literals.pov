// checks float literal forms: integer, decimal, leading/trailing point, exponents
#version 3.7;
#debug concat(str(34, 0, 6), "\n")
#debug concat(str(-2.0, 0, 6), "\n")
#debug concat(str(.3, 0, 6), "\n")
#debug concat(str(0.6, 0, 6), "\n")
#debug concat(str(5., 0, 6), "\n")
#debug concat(str(3.4e6, 0, 6), "\n")
#debug concat(str(2e-5, 0, 8), "\n")
#debug concat(str(1E3, 0, 6), "\n")
#debug concat(str(1.5e+2, 0, 6), "\n")
#debug concat(str(007, 0, 6), "\n")
#debug concat(str(123456789, 0, 0), "\n")
#debug concat(str(0.000001, 0, 6), "\n")

// checks built-in math functions inside user functions
#version 3.7;
#declare F = function(a) { sin(a) + cos(a) + tan(a/4) + sqrt(abs(a)) + exp(-a) + ln(a + 5) + log(a + 5) }
#debug concat(str(F(1), 0, 6), " ", str(F(2.5), 0, 6), "\n")
#declare G = function(a, b) { atan2(a, b) + pow(a, 2) + min(a, b) + max(a, b, 3) + mod(a, b) + div(a, b) }
#debug concat(str(G(7, 2), 0, 6), " ", str(G(-3, 4), 0, 6), "\n")
#declare H = function(a) { floor(a) + ceil(a) * 10 + int(a) * 100 + degrees(radians(a)) }
#debug concat(str(H(2.5), 0, 6), " ", str(H(-2.5), 0, 6), "\n")
#declare K = function(a) { asin(a) + acos(a) + atan(a) + sinh(a) + cosh(a) + tanh(a) + asinh(a) + atanh(a / 2) }
#debug concat(str(K(0.5), 0, 6), "\n")
#declare M = function(a) { acosh(a + 1) + pi * a }
#debug concat(str(M(1), 0, 6), "\n")

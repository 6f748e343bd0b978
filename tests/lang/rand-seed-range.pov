// checks seed() with values outside a 32-bit int (POV-Ray draws as from
// seed(-2^31)) and with a fraction, and rand() on a stream index given as
// a fraction (truncated toward zero).
#version 3.7;
#declare A = seed(1e30);
#declare B = seed(-1e30);
#declare C = seed(1e10);
#declare D = seed(3e9);
#declare E = seed(-2.5);
#declare F = seed(2147483647);
#declare G = seed(-2147483648);
#debug concat(str(rand(A), 0, 10), " ", str(rand(B), 0, 10), " ", str(rand(C), 0, 10), "\n")
#debug concat(str(rand(D), 0, 10), " ", str(rand(E), 0, 10), " ", str(rand(F), 0, 10), "\n")
#debug concat(str(rand(G), 0, 10), " ", str(rand(E + 0.7), 0, 10), " ", str(rand(-0.5), 0, 10), "\n")

// checks float literals and pi inside functions
#version 3.7;
#declare F = function { 1.5e2 + .25 + 3. + pi + x }
#debug concat(str(F(0, 0, 0), 0, 6), "\n")
#declare G = function(a) { 1e-3 * a + 2E1 }
#debug concat(str(G(5), 0, 6), "\n")

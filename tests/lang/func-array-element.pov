// func-array-element.pov: an element of an array of functions called in a
// function body (F[K](x, y, z)) and outside one, and a float element used
// as a constant. As in POV-Ray, the indices are read when the function is
// defined (K changed later does not change G), and a fractional index is
// truncated. The expected output is what POV-Ray 3.7.0.10 prints.
#version 3.7;
#declare F = array[2] { function { x + 2*y }, function(a, b, c) { a * 10 + c } }
#declare K = 1;
#declare G = function { F[K](x, y, z) + F[K-1](x, y, 0) }
#debug concat("a ", str(G(1, 2, 3), 0, 6), "\n")
#declare G2 = function { F[0.7](x, y, z) }
#debug concat("b ", str(G2(1, 2, 3), 0, 6), "\n")
#declare A2 = array[2][2] { {function { 1 }, function { 2 }}, {function { 3 }, function { x }} }
#declare G3 = function { A2[1][1](x, 0, 0) + A2[1][0](0, 0, 0) }
#debug concat("c ", str(G3(5, 2, 3), 0, 6), "\n")
#debug concat("d ", str(A2[1][1](7, 2, 3), 0, 6), "\n")
#debug concat("e ", str(F[K](1, 2, 3), 0, 6), "\n")
#declare K = 0;
#debug concat("f ", str(G(1, 2, 3), 0, 6), "\n")
#declare A = array[2] { 1.5, 2.5 }
#declare G4 = function { A[1] + x }
#debug concat("g ", str(G4(1, 2, 3), 0, 6), "\n")
#declare G5 = function(u) { F[1](u, 0, 1) * A[0] }
#debug concat("h ", str(G5(2), 0, 6), "\n")

// text-shared.pov: texts that share glyphs, traced before and after they
// are copied: the same letters in two texts of one font, a text traced
// and then copied and moved, inside() on both, and their extents.
// lucent keeps each glyph's outline once per font for every text, and a
// text makes its pieces when first traced; the answers must not depend on
// which text came first. Rounded to 3 decimals (POV-Ray's text carries a fuzz of about 3e-5).
#version 3.7;
#macro Rnd(X) (floor(X * 1e3 + 0.5) / 1e3) #end
#macro R3(V) concat(str(Rnd(V.x), 0, 3), ",", str(Rnd(V.y), 0, 3), ",", str(Rnd(V.z), 0, 3)) #end
#macro TR(S, T, O, D)
	#local N = <0, 0, 0>;
	#local P = trace(T, O, D, N);
	#debug concat(S, ": ", R3(P), " normal ", R3(N), "\n")
#end
#declare A = text { ttf "timrom.ttf" "AVA" 1, 0 }
TR("A front", A, <0.1, 0.05, -5>, z)
TR("A side", A, <-5, 0.2, 0.5>, x)
TR("A back", A, <1.7, 0.05, 5>, -z)
#declare B = object { A translate <1, 2, 0> }
TR("B front", B, <1.1, 2.05, -5>, z)
TR("B side", B, <-5, 2.2, 0.5>, x)
#declare C = text { ttf "timrom.ttf" "VAVA" 0.5, <0.1, 0.05, 0> }
TR("C front", C, <0.9, 0.35, -5>, z)
TR("C side", C, <-5, 0.3, 0.25>, x)
TR("C down", C, <1.0, 5, 0.25>, -y)
#macro IN(S, T, P) #debug concat(S, ": ", str(inside(T, P), 0, 0), "\n") #end
IN("A at 0.3,0.3", A, <0.3, 0.3, 0.5>)
IN("A at 0.36,0.5", A, <0.36, 0.5, 0.5>)
IN("B at 1.3,2.3", B, <1.3, 2.3, 0.5>)
IN("C at 0.9,0.35", C, <0.9, 0.35, 0.25>)
IN("C above", C, <0.9, 0.35, 0.75>)
#declare D = object { C rotate 90 * y }
TR("D from x", D, <5, 0.35, -0.9>, -x)
#debug concat("A ", R3(min_extent(A)), " / ", R3(max_extent(A)), "\n")
#debug concat("B ", R3(min_extent(B)), " / ", R3(max_extent(B)), "\n")
#debug concat("C ", R3(min_extent(C)), " / ", R3(max_extent(C)), "\n")

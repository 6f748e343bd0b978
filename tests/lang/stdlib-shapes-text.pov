// stdlib-shapes-text.pov: the text macros of shapes.inc (Text_Space,
// Text_Width, Circle_Text, Bevelled_Text) with POV-Ray's timrom.ttf: widths,
// the x and y extents of Circle_Text's objects and points where rays meet
// Bevelled_Text's. Rounded to 3 decimals: POV-Ray's own figures carry a
// fuzz of about 3e-5 (its text bounds are a little larger than the glyphs).
#version 3.7;
#include "shapes.inc"
// Rnd(X): X rounded to 3 decimals (no -0).
#macro Rnd(X) (floor(X * 1e3 + 0.5) / 1e3) #end
#macro R2(V) concat(str(Rnd(V.x), 0, 3), ",", str(Rnd(V.y), 0, 3)) #end
#macro R3(V) concat(R2(V), ",", str(Rnd(V.z), 0, 3)) #end
#debug concat("Align ", str(Align_Left, 0, 0), " ", str(Align_Right, 0, 0), " ", str(Align_Center, 0, 0), "\n")
#macro W(S, Size, Sp)
	#debug concat("\"", S, "\" ", str(Size, 0, 1), " ", str(Sp, 0, 1), ": space ",
		str(Rnd(Text_Space("timrom.ttf", S, Size, Sp)), 0, 3), " width ",
		str(Rnd(Text_Width("timrom.ttf", S, Size, Sp)), 0, 3), "\n")
#end
W("AV", 1, 0) W("AV", 2, 0.1) W("A", 1, 0) W("H", 1, 0.5) W("A V", 1, 0) W("Ho", 3, 0.2) W("oH", 1, 0)
W("VA", 1, 0) W("To Wa", 0.5, 0.05)
#macro E(S, T) #debug concat(S, ": ", R2(min_extent(T)), " / ", R2(max_extent(T)), "\n") #end
E("left 90", object { Circle_Text("timrom.ttf", "Hello", 1, 0, 0.2, 2, 0, Align_Left, 90) })
E("left 90 inverted", object { Circle_Text("timrom.ttf", "Hello", 1, 0, 0.2, 2, 1, Align_Left, 90) })
E("center 0", object { Circle_Text("timrom.ttf", "Hello", 0.5, 0.1, 0.3, 1.5, 0, Align_Center, 0) })
E("right 30 inverted", object { Circle_Text("timrom.ttf", "Hello", 0.5, 0.1, 0.3, 1.5, 1, Align_Right, 30) })
E("AV center 90", object { Circle_Text("timrom.ttf", "AV", 1, 0, 0.2, 3, 0, Align_Center, 90) })
#macro TR(S, B, O, D)
	#local P = trace(B, O, D);
	#debug concat(S, ": ", R3(P), "\n")
#end
#declare B = Bevelled_Text("timrom.ttf", "H", 4, 30, 0.05, 0.3, 0, 0)
TR("bevel 1", B, <0.1, 0.3, -1>, z)
TR("bevel 2", B, <0.2, 0.3, 0.1>, -x)
TR("bevel 3", B, <-1, 0.3, 0.02>, x)
TR("bevel 4", B, <-1, 0.3, 0.2>, x)
TR("bevel 5", B, <2, 0.3, 0.02>, -x)
#declare B = Bevelled_Text("timrom.ttf", "Hi", 3, 45, 0.1, 0.5, 0.1, 1)
TR("bevel 6", B, <0.1, 0.3, -1>, z)
TR("bevel 7", B, <-1, 0.3, 0.05>, x)
TR("bevel 8", B, <2, 0.45, 0.05>, -x)
TR("bevel 9", B, <0.45, 2, 0.03>, -y)

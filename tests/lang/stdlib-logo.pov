// stdlib-logo.pov: logo.inc's three logos, shown by the points where rays
// meet them (and the normals there) and by which points lie inside them.
// The rays run through the ball, the crescent's thick right side and thin
// top, the open left side, the tail and the gap between tail and ball;
// from the front, the back, and sideways in the plane z = 0 (z = -0.1 for
// the bevelled logo, which lies behind z = 0). Not the extents: POV-Ray's
// logos report a bounding box much larger than the shape (x from -1.31 to
// 1.18 where the shape spans -0.55 to 0.74), lucent's are its own. Nor the
// normals of the flat logo: POV-Ray's is a prism object, and trace() gives
// a prism's normals as its spline's winding makes them (here <0, 0, -1> on
// both caps, and pointing inwards on the sides); lucent's is built from
// other shapes and gives the outward normals. Nor the bevelled logo from
// behind: rays from behind go through the back of POV-Ray's crescent and
// tail and meet their bevelled front from inside; lucent's back face is
// closed. Normals are rounded to 3 decimals (POV-Ray's bevel differs from
// lucent's in the 4th).
#version 3.7;
#include "logo.inc"
// Rnd(V): V rounded to Digits decimals (no -0 from rounding): 4, but 3 for
// the bevelled logo, whose inner curve differs from POV-Ray's by 1e-4.
#declare Digits = 4;
#macro Rnd(V) (<floor(V.x * pow(10, Digits) + 0.5), floor(V.y * pow(10, Digits) + 0.5), floor(V.z * pow(10, Digits) + 0.5)> / pow(10, Digits)) #end
// Hit(Name, O, From, Dir, Normal): where the ray From + t Dir meets O, and
// the normal there if Normal is true.
#macro Hit(Name, O, From, Dir, Normal)
	#local N = <0, 0, 0>;
	#local P = trace(O, From, Dir, N);
	#if (vlength(N) > 0)
		#debug concat(Name, " ", vstr(3, From, ",", 0, 2), " hit ", vstr(3, Rnd(P), ", ", 0, Digits),
			#if (Normal) " normal ", vstr(3, Rnd(N), ", ", 0, 3), #end "\n")
	#else
		#debug concat(Name, " ", vstr(3, From, ",", 0, 2), " miss\n")
	#end
#end
#macro Probe(Name, O, Zs, Normals, Back)
	// From the front and from the back.
	#for (I, 0, 8)
		#local P = array[9] { <0.09, 0.37, 0>, <0.62, 0.4, 0>, <0.1, 0.85, 0>, <-0.45, 0.4, 0>,
			<-0.35, -0.5, 0>, <-0.5, -0.93, 0>, <0.1, 0.05, 0>, <-0.3, 0.1, 0>, <0.3, -0.1, 0> }
		Hit(Name, O, P[I] - 5 * z, z, Normals)
		#if (Back) Hit(Name, O, P[I] + 5 * z, -z, Normals) #end
	#end
	// Sideways, at depth Zs.
	#for (Y, -0.9, 0.9, 0.3)
		Hit(Name, O, <-3, Y, Zs>, x, Normals)
		Hit(Name, O, <3, Y, Zs>, -x, Normals)
	#end
	#for (X, -0.5, 0.7, 0.3)
		Hit(Name, O, <X, 3, Zs>, -y, Normals)
		Hit(Name, O, <X, -3, Zs>, y, Normals)
	#end
	#local S = "";
	#for (I, 0, 11)
		#local Q = array[12] { <0.09, 0.37, Zs>, <0.6, 0.4, Zs>, <0.1, 0.87, Zs>, <-0.45, 0.4, Zs>,
			<-0.32, -0.5, Zs>, <0.1, 0.05, Zs>, <0.09, 0.37, 0.3>, <0.6, 0.4, -0.3>, <-0.8, 0, Zs>,
			<0.4, -0.4, Zs>, <0.09, 0.7, Zs>, <0.5, 0.4, Zs> }
		#local S = concat(S, str(inside(O, Q[I]), 0, 0));
	#end
	#debug concat(Name, " inside ", S, "\n")
#end
Probe("Povray_Logo", Povray_Logo, 0, true, true)
Probe("Povray_Logo_Prism", Povray_Logo_Prism, 0, false, true)
#declare Digits = 3;
Probe("Povray_Logo_Bevel", Povray_Logo_Bevel, -0.02, true, false)

// strings.inc: every macro. Long strings print in pieces of 60 characters
// (the #debug stream wraps lines longer than 80).
#version 3.7;
#include "strings.inc"
#macro P(N, S) #debug concat(N, " [", S, "]\n") #end
#macro Long(N, S)
	#debug concat(N, " length ", str(strlen(S), 0, 0), "\n")
	#local I = 1;
	#while (I <= strlen(S))
		#debug concat("  ", substr(S, I, min(60, strlen(S) - I + 1)), "\n")
		#local I = I + 60;
	#end
#end
P("CRGBStr", CRGBStr(rgb <0.25, 0.5, 1>, 0, 3))
P("CRGBStr pad", CRGBStr(rgb <0.25, 0.5, 1>, 8, 2))
P("CRGBStr zero", CRGBStr(rgb <0.25, 0.5, 1>, -8, 2))
P("CRGBFTStr", CRGBFTStr(rgbft <0.25, 0.5, 1, 0.125, 0.75>, 0, 3))
P("CRGBFTStr pad", CRGBFTStr(rgbft <0.25, 0.5, 1, 0.125, 0.75>, 6, 1))
P("CRGBFTStr rgb", CRGBFTStr(rgb <0.25, 0.5, 1>, 0, 2))
P("Str", Str(1.5))
P("Str", Str(-0.123456789))
P("Str", Str(12345678))
P("VStr2D", VStr2D(<1.5, -2.25>))
P("VStr", VStr(<1.5, -2.25, 3>))
P("Vstr2D", Vstr2D(<1.5, -2.25>, 0, 2))
P("Vstr", Vstr(<1.5, -2.25, 3>, 7, 3))
P("Vstr", Vstr(<1.5, -2.25, 3>, -7, 1))
Long("Triangle_Str", Triangle_Str(<0,0,0>, <1,0,0>, <0.5,1,0.25>))
Long("Smooth_Triangle_Str", Smooth_Triangle_Str(<0,0,0>, y, <1,0,0>, <0,1,1>, <0.5,1,0.25>, z))
#declare Q = 7;
#declare R = Parse_String("Q * 2");
#debug concat("Parse_String ", str(R, 0, 2), "\n")
#declare S = sphere { 0, Parse_String("Q") }
#debug concat("Parse_String sphere ", vstr(3, max_extent(S), ",", 0, 2), "\n")
Parse_String("#declare Made = \"made by Parse_String\";")
#debug concat(Made, "\n")

// colors.inc: CRGB2HSL, CRGB2HSV, CHSL2RGB and CHSV2RGB on colours whose
// components are exact in binary (POV-Ray keeps colours in single
// precision, so other values print differently in the last digits).
#version 3.7;
#include "colors.inc"
#macro Show(Name, C)
	#debug concat(Name, " ", vstr(5, C, ",", 0, 6), "\n")
#end
#declare Cs = array[12] {
	rgb <0.25, 0.5, 0.75>, rgbft <1, 0.5, 0, 0.25, 0.125>, rgb 0.5, rgb 0, rgb 1,
	rgb <0.875, 0.125, 0.25>, rgb <0.125, 0.75, 0.25>, rgb <2, 0.5, -0.5>,
	rgb <0.25, 0.25, 0.875>, rgb <0.625, 0.625, 0.25>, rgb <0.5, 0.25, 0.5>, rgb <0.25, 0.5, 0.5>
}
#for (I, 0, 11)
	Show(concat("HSL ", str(I, 0, 0)), CRGB2HSL(Cs[I]))
	Show(concat("HSV ", str(I, 0, 0)), CRGB2HSV(Cs[I]))
	// Round trips.
	Show("  back from HSL", CHSL2RGB(CRGB2HSL(Cs[I])))
	Show("  back from HSV", CHSV2RGB(CRGB2HSV(Cs[I])))
#end
#declare Hs = array[12] {
	<0, 0.5, 0.5>, <30, 1, 0.25>, <120, 0.25, 0.75>, <200, 0.75, 0.625>, <300, 1, 1>,
	<360, 0.5, 0.5>, <420, 0.5, 0.5>, <-60, 0.5, 0.5>, <90, 0, 0.5>, <180, 1, 0.5>,
	<240, 0.5, 0>, <270, 0.5, 0.125>
}
#for (I, 0, 11)
	Show(concat("from HSL ", str(I, 0, 0)), CHSL2RGB(Hs[I]))
	Show(concat("from HSV ", str(I, 0, 0)), CHSV2RGB(Hs[I]))
#end
// Filter and transmit pass through.
Show("HSL ft", CHSL2RGB(<200, 0.75, 0.625, 0.5, 0.25>))
Show("HSV ft", CHSV2RGB(<200, 0.75, 0.625, 0.5, 0.25>))
// A colour given as a plain vector or float.
Show("HSV vec", CRGB2HSV(<0.25, 0.5, 1>))
Show("HSV float", CRGB2HSV(0.5))

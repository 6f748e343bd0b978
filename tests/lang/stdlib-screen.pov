// screen.inc: where Screen_Object and Screen_Plane put things (centre and
// size of their bounding boxes) for the default camera and after each
// Set_Camera_ macro: confined or not, with spacing, scaling, zoom, angle,
// aspect, sky, location and look_at. (Printed to 4 decimals: POV-Ray keeps
// bounding boxes in single precision.)
#version 3.7;
#include "screen.inc"
#macro E(O)
	#local C = (min_extent(O) + max_extent(O)) / 2 + 1e-7;
	#debug concat(vstr(3, C, ",", 0, 4), "  ", vstr(3, max_extent(O) - min_extent(O), ",", 0, 4), "\n")
#end
#declare B = box { <0.1, 0.2, 0.3>, <0.15, 0.3, 0.4> }
#declare T = texture { pigment { rgb 1 } }
#macro Try()
	E(Screen_Object(B, <0, 0>, 0, false, 1))
	E(Screen_Object(B, <1, 1>, 0, false, 1))
	E(Screen_Object(B, <0.3, 0.6>, 0.1, false, 0.5))
	E(Screen_Object(B, <0, 0>, 0, true, 1))
	E(Screen_Object(B, <1, 1>, 0, true, 1))
	E(Screen_Object(B, <0.3, 0.6>, 0.1, true, 1))
	E(Screen_Object(B, <0.3, 0.6>, <0.1, 0.2>, true, 0.5))
	E(Screen_Object(B, <-1, 2>, 0.1, true, 1))
	E(Screen_Plane(T, 1, <0, 0>, <1, 1>))
	E(Screen_Plane(T, 0.5, <0.2, 0.3>, <0.6, 0.9>))
	#debug "--\n"
#end
Try()
Set_Camera_Angle(90) Try()
Set_Camera_Zoom(2) Try()
Set_Camera_Aspect_Ratio(2) Try()
Set_Camera_Aspect(3, 4) Try()
Set_Camera_Angle(40) Try()
Reset_Camera() Try()
Set_Camera_Location(<1, 2, 3>) Try()
Set_Camera_Look_At(<4, 2, 3>) Try()
Set_Camera_Sky(<1, 1, 1>) Try()
Reset_Camera() Set_Camera_Sky(x) Try()
Set_Camera(<1, 2, -3>, <4, 6, 3>, 60) Try()
Set_Camera_Zoom(0.5) Try()

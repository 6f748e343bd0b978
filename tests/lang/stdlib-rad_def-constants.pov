// rad_def.inc: the quality constants. (Rad_Settings itself goes inside
// radiosity { }, which lucent does not parse.)
#version 3.7;
#include "rad_def.inc"
#debug concat(str(Radiosity_Default, 0, 0), " ", str(Radiosity_Debug, 0, 0), " ",
	str(Radiosity_Fast, 0, 0), " ", str(Radiosity_Normal, 0, 0), " ",
	str(Radiosity_2Bounce, 0, 0), " ", str(Radiosity_Final, 0, 0), "\n")
#debug concat(str(Radiosity_OutdoorLQ, 0, 0), " ", str(Radiosity_OutdoorHQ, 0, 0), " ",
	str(Radiosity_OutdoorLight, 0, 0), " ", str(Radiosity_IndoorLQ, 0, 0), " ",
	str(Radiosity_IndoorHQ, 0, 0), "\n")

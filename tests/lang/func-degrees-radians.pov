// checks degrees() and radians() conversions
#version 3.7;
#debug concat(str(degrees(pi), 0, 6), " ", str(degrees(1), 0, 6), " ", str(degrees(-pi/2), 0, 6), "\n")
#debug concat(str(radians(180), 0, 6), " ", str(radians(90), 0, 6), " ", str(radians(-45), 0, 6), " ", str(radians(1), 0, 8), "\n")
#debug concat(str(degrees(radians(123.456)), 0, 6), "\n")

// checks atan2 in all four quadrants and with a zero second argument
#version 3.7;
#debug concat(str(atan2(1, 1), 0, 6), "\n")
#debug concat(str(atan2(1, -1), 0, 6), "\n")
#debug concat(str(atan2(-1, -1), 0, 6), "\n")
#debug concat(str(atan2(-1, 1), 0, 6), "\n")
#debug concat(str(atan2(1, 0), 0, 6), "\n")
#debug concat(str(atan2(-1, 0), 0, 6), "\n")
#debug concat(str(atan2(0, 1), 0, 6), "\n")
#debug concat(str(atan2(0, -1), 0, 6), "\n")
#debug concat(str(atan2(3, 1), 0, 6), "\n")

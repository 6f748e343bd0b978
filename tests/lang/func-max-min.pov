// checks max and min with two and more arguments
#version 3.7;
#debug concat(str(max(1, 2), 0, 6), " ", str(max(2, 1), 0, 6), " ", str(max(-1, -2), 0, 6), "\n")
#debug concat(str(min(1, 2), 0, 6), " ", str(min(2, 1), 0, 6), " ", str(min(-1, -2), 0, 6), "\n")
#debug concat(str(max(3, 9, 2, 7), 0, 6), " ", str(min(3, 9, 2, 7), 0, 6), "\n")
#debug concat(str(max(1, 2, 3, 4, 5, 6, 7, 8, 9, 10), 0, 6), " ", str(min(10, 9, 8, 7, 6, 5, 4, 3, 2, 1), 0, 6), "\n")
#debug concat(str(max(0.5, 0.25, 0.75), 0, 6), " ", str(min(-0.5, 0.25, -0.75), 0, 6), "\n")
#debug concat(str(max(2, 2), 0, 6), " ", str(min(1+1, 3-2), 0, 6), "\n")

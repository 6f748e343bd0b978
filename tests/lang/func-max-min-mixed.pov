// checks max/min with negative, fractional and equal arguments, and nested max/min
#version 3.7;
#debug concat(str(max(-1, -1.5, -0.5), 0, 2), " ", str(min(0.1, 0.01, 0.001), 0, 3), "\n")
#debug concat(str(max(min(5, 3), min(2, 4)), 0, 0), " ", str(min(max(1, 2), max(0, 3)), 0, 0), "\n")
#debug concat(str(max(1e-20, 0), 0, 0), " ", str(min(-1e20, 1), 0, 0), "\n")

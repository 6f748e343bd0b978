// checks built-in functions nested inside each other and inside vectors
#version 3.7;
#debug concat(str(max(abs(-3), sqrt(16), pow(2, 1.5)), 0, 6), "\n")
#debug concat(str(int(degrees(atan2(1, 1))), 0, 6), "\n")
#debug concat(str(vlength(vcross(vnormalize(<1,0,0>), vnormalize(<1,1,0>))), 0, 6), "\n")
#debug concat(str(floor(log(12345)), 0, 6), " ", str(mod(int(exp(3)), 7), 0, 6), "\n")
#debug concat(vstr(3, <sin(0), cos(0), min(4, max(1, 2))>, ",", 0, 6), "\n")

// checks pattern functions (gradient, checker, boxed) at a few points
#version 3.7;
#declare Gx = function { pattern { gradient x } }
#declare Ck = function { pattern { checker } }
#declare Bx = function { pattern { boxed } }
#debug concat(str(Gx(0.25, 0, 0), 0, 6), " ", str(Gx(1.75, 5, 5), 0, 6), " ", str(Gx(-0.25, 0, 0), 0, 6), "\n")
#debug concat(str(Ck(0.5, 0.5, 0.5), 0, 6), " ", str(Ck(1.5, 0.5, 0.5), 0, 6), " ", str(Ck(1.5, 1.5, 0.5), 0, 6), "\n")
#debug concat(str(Bx(0, 0, 0), 0, 6), " ", str(Bx(0.5, 0.25, 0), 0, 6), " ", str(Bx(2, 0, 0), 0, 6), "\n")

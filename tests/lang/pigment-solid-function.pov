// checks declared pigments, colour identifiers and quick_color through function { pigment { } }
#version 3.7;
#declare C = rgbft <0.2, 0.4, 0.6, 0.1, 0.05>;
#declare P = pigment { C }
#declare Q = pigment { P scale 2 rotate 30*y quick_color rgb 1 }
#declare R = pigment { color red 0.5 green 0.25 }
#declare FP = function { pigment { P } }
#declare FQ = function { pigment { Q } }
#declare FR = function { pigment { R translate 1 } }
#declare FS = function { FQ(x, y, z).green * 10 + FR(x, y, z).red }
#debug concat(vstr(5, FP(1, 2, 3), ",", 0, 6), "\n")
#debug concat(vstr(5, FQ(-1, 0, 3), ",", 0, 6), " ", str(FQ(0, 0, 0).gray, 0, 6), "\n")
#debug concat(vstr(5, FR(0, 0, 0), ",", 0, 6), " ", str(FS(1, 1, 1), 0, 6), "\n")
#declare V = FP(0, 0, 0) + <1, 1, 1>;
#debug concat(vstr(3, V, ",", 0, 6), "\n")

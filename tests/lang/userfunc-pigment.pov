// checks a pigment function (a colour-valued function) and .gray/.red on its result
#version 3.7;
#declare foo = function {
  pigment {
    color red 1
  }
}
#declare Vec = foo(1, 2, 3);
#debug concat(vstr(5, Vec, ",", 0, 6), "\n")
#declare G = function { pigment { gradient x color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] } } }
#debug concat(vstr(5, G(0.5, 0, 0), ",", 0, 6), "\n")
#debug concat(str(G(0.25, 0, 0).gray, 0, 6), " ", str(G(0.75, 0, 0).red, 0, 6), "\n")

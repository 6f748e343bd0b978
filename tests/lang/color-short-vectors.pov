// checks colour keywords given shorter vectors than they expect (missing components become 0)
#version 3.7;
#declare D = rgbf <1,2,3>;
#debug concat(vstr(5, D, ",", 0, 1), "\n")
#declare E = rgbft <1,2,3>;
#debug concat(vstr(5, E, ",", 0, 1), "\n")
#declare F = rgbt <1,2>;
#debug concat(vstr(5, F, ",", 0, 1), "\n")
#declare G = rgbft <1,2,3,4>;
#debug concat(vstr(5, G, ",", 0, 1), "\n")

// checks colour expressions used inside a pigment declaration parse and keep identifiers usable
#version 3.7;
#declare Base = rgb <0.2, 0.3, 0.4>;
#declare P = pigment { color Base * 2 filter 0.5 }
#declare Q = pigment { rgbf <1, 0, 0, 0.5> }
#debug concat(vstr(5, Base * 2, ",", 0, 6), "\n")
#debug "pigments declared\n"

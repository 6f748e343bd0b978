// checks that vstr does not spread a float over all components (unlike the manual says): a float prints as <F,0,...>
#version 3.7;
#declare F = 2.5;
#debug concat(vstr(3, F, ",", 0, 6), "\n")
#debug concat(vstr(2, F, ",", 0, 6), "\n")
#debug concat(vstr(4, F, ",", 0, 6), "\n")
#debug concat(vstr(5, F, ",", 0, 6), "\n")
#debug concat(vstr(3, F*x, ",", 0, 6), "\n")

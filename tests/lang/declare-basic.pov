// checks #declare of floats, vectors, colours and strings and reading them back
#version 3.7;
#declare F = 1.25;
#declare V = <1, 2, 3>;
#declare C = rgb <0.1, 0.2, 0.3>;
#declare S = "hello";
#debug concat(str(F, 0, 6), "\n")
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#debug concat(S, "\n")

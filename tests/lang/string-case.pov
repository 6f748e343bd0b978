// checks strupr() and strlwr() and that they leave the original unchanged
#version 3.7;
#declare S = "Hello There! 123 abc XYZ";
#debug concat(strupr(S), "\n")
#debug concat(strlwr(S), "\n")
#debug concat(S, "\n")
#debug concat(strupr(""), "|", strlwr("_-+"), "\n")
#debug concat(strlwr(strupr("MiXeD")), "\n")

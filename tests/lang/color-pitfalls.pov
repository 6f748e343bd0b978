// checks the manual's colour pitfalls: a bare float colour sets all five components, rgb sets three
#version 3.7;
#declare My_Color = rgbft <0.2, 0.4, 0.6, 0.1, 0.3>;
#declare Red_Half = color red 0.5;
#declare A = My_Color + Red_Half;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = My_Color * Red_Half;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = color 0.4;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = color rgb 0.4;
#debug concat(vstr(5, D, ",", 0, 6), "\n")

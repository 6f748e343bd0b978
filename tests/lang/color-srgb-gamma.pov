// checks that an sRGB colour is brought to the working gamma when assumed_gamma is not 1
#version 3.7;
global_settings { assumed_gamma 2.2 }
#declare A = srgb <0.5, 0.2, 0.04>;
#declare B = srgbft <0.9, 0.01, 1, 0.3, 0.4>;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare I = 0;
#while (I < 3)
  #declare C = srgb I/4;
  #debug concat(str(C.red, 0, 6), "\n")
  #declare I = I + 1;
#end

// checks vectors and colours in expressions evaluated many times
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare R = seed(3);
#declare I = 0;
#while (I < 4)
  #declare P = <I, 2 * I, -I> + 1;
  #declare Q = x * I + y - z / 2 + <1, 2> * 3;
  #declare C = rgbf <I / 4, 0.5, 1, 0.25> * 0.5;
  #declare D = srgb <0.5, I / 4, 1>;
  #declare W = <rand(R), rand(R) * 2, 40 * rand(R) - 20>;
  #declare E = (P = <I + 1, 2 * I + 1, 1 - I>) + (Q < 3);
  #debug concat(vstr(3, P, ",", 0, 3), " | ", vstr(3, Q, ",", 0, 3), " | ", vstr(5, C, ",", 0, 4), " | ",
                vstr(3, D, ",", 0, 4), " | ", vstr(3, W, ",", 0, 5), " | ", vstr(3, E, ",", 0, 0), "\n")
  #declare I = I + 1;
#end

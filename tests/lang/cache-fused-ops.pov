// checks arithmetic with a number on one side (compiled as one step):
// k - x, k / x, x - k, x / k, k + x, k * x on floats and vectors, and
// rand of a variable stream
#version 3.7;
#declare A = 3;
#declare V = <1, 2, 4>;
#declare I = 0;
#while (I < 2)
  #debug concat(str(2 - A, 0, 3), " ", str(8 / A, 0, 6), " ", str(A - 2, 0, 3), " ", str(A / 8, 0, 6), " ",
                str(2 + A, 0, 3), " ", str(2 * A, 0, 3), " ", str(1 - 2 * A / 4 + 1, 0, 6), "\n")
  #declare W = 10 - V;
  #debug concat(vstr(3, W, ",", 0, 3), " ", vstr(3, 8 / V, ",", 0, 3), " ", vstr(3, V - 1, ",", 0, 3), " ",
                vstr(3, V / 2, ",", 0, 3), " ", vstr(3, 3 * V, ",", 0, 3), " ", vstr(3, 1 + V, ",", 0, 3), "\n")
  #declare C = rgb 1 - <0.25, 0.5, 0.75>;
  #debug concat(vstr(3, C, ",", 0, 3), "\n")
  #declare A = A + 1;
  #declare I = I + 1;
#end
#declare R1 = seed(7);
#declare R2 = seed(7);
#declare S = R1;
#declare J = 0;
#while (J < 3)
  #debug concat(str(rand(S), 0, 6), " ", str(rand(R2), 0, 6), " ", str(40 * rand(R1) - 20, 0, 6), "\n")
  #declare J = J + 1;
#end

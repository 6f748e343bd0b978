// checks expressions evaluated again and again in a loop while the kinds
// of their identifiers change (float, vector, float), a vector literal of
// expressions, a colour keyword on one, and rand() inside a vector
#version 3.7;
#declare R = seed(7);
#declare I = 0;
#while (I < 4)
  #if (I = 2)
    #declare A = <1, 2, 3>;
  #else
    #declare A = I;
  #end
  #declare S = A * 2 + 1;
  #declare V = <I * 2, I - 1, (I > 1 ? 5 : 6)>;
  #declare C = rgb <I / 4, 1, 0.5>;
  #declare P = <rand(R), I>;
  #debug concat(vstr(3, S, ",", 0, 3), " | ", vstr(3, V, ",", 0, 3), " | ", vstr(5, C, ",", 0, 3), " | ",
                vstr(2, P, ",", 0, 6), "\n")
  #declare I = I + 1;
#end

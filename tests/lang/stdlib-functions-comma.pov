// functions.inc: f_comma (ball, tail, the part cut off below z = 0, the y
// axis, negative and zero sizes) and f_helical_torus (twist, threshold,
// second fatness, fractional and zero loop counts, grooves, the y and -z
// axes, a negative second fatness).
#version 3.7;
#include "functions.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 10), "\n") #end
#declare Pts = array[8] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>,
  <2.7,1.3,-0.8>, <0,0.2,0.7>, <-0.8,0.1,0.3>, <-1.2,0.25,-0.3>, <0.45,0,0.35>}
#declare Sizes = array[5] {1, 2.5, 0.3, -1.5, 0}
#for (I, 0, 7)
  #for (J, 0, 4)
    #declare P = Pts[I];
    S("comma", f_comma(P.x, P.y, P.z, Sizes[J]))
  #end
#end
S("comma axis", f_comma(0, 0, 0, 1))
S("comma axis", f_comma(0, 0.1, 0, 2))
S("comma axis", f_comma(0, -0.7, 0, -1))

#declare Sets = array[10][10] {
  {1, 0.5, 0.3, 0.8, 0.2, 1.5, 0.7, 0.4, 0.6, 0.9},
  {1, 3, 0, 0.2, 0, 0.3, 1, 0, 0, 0},
  {1, 3, 1, 0.2, 0, 0.3, 1, 0, 0, 0},
  {5, 3, -0.7, 0.2, 0.4, 2, 1, 0, 0, 0},
  {5, 2.5, 0, 0.2, 0, 2, 0.5, 0, 0, 0},
  {5, 3, 1.3, 0.2, 0.4, 2, 3.3, 0, 0, 0},
  {5, 3, 0, 0.2, 0, 2, 1, 1.3, 0.5, 0.6},
  {1, 2.5, 0.7, 0.2, 0, 0.3, 1, 1.5, 0.6, 0.8},
  {3.7, 0, 0, -0.1, -1, -0.7, 0.9, 2.6, 0.4, -0.4},
  {4, 3, 0, 0.2, 0.1, 2, -1, 0, 0, 0}}
#declare TPts = array[8] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>,
  <2.7,1.3,-0.8>, <4.1,-1.2,2>, <-1.5,0.4,-4.2>, <0,0.2,0>, <0,0.3,-2>}
#for (J, 0, 9)
  #for (I, 0, 7)
    #declare P = TPts[I];
    S("helical_torus", f_helical_torus(P.x, P.y, P.z, Sets[J][0], Sets[J][1],
      Sets[J][2], Sets[J][3], Sets[J][4], Sets[J][5], Sets[J][6], Sets[J][7],
      Sets[J][8], Sets[J][9]))
  #end
#end

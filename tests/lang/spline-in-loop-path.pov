// checks sampling a spline along a path and measuring its approximate length
#version 3.7;
#declare Path = spline {
  natural_spline
  0, <0, 0, 0>
  1, <1, 1, 0>
  2, <2, 0, 0>
  3, <3, -1, 1>
}
#declare Len = 0;
#declare Prev = Path(0);
#for (I, 1, 300)
  #declare P = Path(I / 100);
  #declare Len = Len + vlength(P - Prev);
  #declare Prev = P;
#end
#debug concat("length ~ ", str(Len, 0, 6), "\n")

// parse-macro.pov: parse-speed benchmark: 200,000 calls of a one-line
// macro defined in an include file.
#version 3.7;
#include "bench-macros.inc"
#declare I = 0;
#declare S = 0;
#while (I < 200000)
  #declare S = Add(S, I);
  #declare I = I + 1;
#end
#debug concat("sum ", str(S, 0, 0), "\n")

// checks #include in the middle of an expression (the file supplies tokens)
#version 3.7;
#declare V = <1, 
#include "inc/number.inc"
, 3>;
#debug concat(vstr(3, V, ",", 0, 0), "\n")
#declare F = 100 + 
#include "inc/number.inc"
;
#debug concat(str(F, 0, 0), "\n")

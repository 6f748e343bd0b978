// checks including a file that defines a macro twice (redefinition replaces it)
#version 3.7;
#include "inc/macros.inc"
#include "inc/macros.inc"
#debug concat(str(Inc_Square(4), 0, 0), "\n")

// checks #undef inside an include: it removes the include's local, uncovering the global
#version 3.7;
#declare A = 123;
#include "inc/undef-local.inc"
#debug concat("main: A=", str(A, 0, 0), "\n")

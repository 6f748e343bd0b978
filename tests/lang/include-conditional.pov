// checks an include guard made with #ifndef
#version 3.7;
#include "inc/guarded.inc"
#include "inc/guarded.inc"
#include "inc/guarded.inc"
#debug concat("Guarded_Loads=", str(Guarded_Loads, 0, 0), "\n")

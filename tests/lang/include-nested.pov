// checks nested includes (an include that includes another)
#version 3.7;
#debug "main before\n"
#include "inc/nest1.inc"
#debug concat("main after, depth reached ", str(Depth, 0, 0), "\n")

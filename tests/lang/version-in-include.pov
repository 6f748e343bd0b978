// checks that a #version in an include file stays in effect after the include ends
#version 3.7;
#include "inc/setversion.inc"
#debug concat("after include: ", str(version, 0, 2), "\n")
#version 3.7;
#debug concat("restored: ", str(version, 0, 2), "\n")

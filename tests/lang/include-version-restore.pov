// checks an include that changes #version and restores it with a #local copy
#version 3.7;
#debug concat("before: ", str(version, 0, 2), "\n")
#include "inc/oldversion.inc"
#debug concat("after: ", str(version, 0, 2), "\n")

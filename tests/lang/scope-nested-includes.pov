// checks locals across nested include files: an inner include sees the outer include's locals
#version 3.7;
#declare Level = "main";
#include "inc/scope-outer.inc"
#debug concat("main: Level=", Level, "\n")

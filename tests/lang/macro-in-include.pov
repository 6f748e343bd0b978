// checks calling a macro defined in an include file, and a macro in the include calling back into the main file
#version 3.7;
#macro Main_Helper(X) (X + 1000) #end
#include "inc/macros.inc"
#debug concat(str(Inc_Square(9), 0, 0), " ", str(Inc_Calls_Main(5), 0, 0), "\n")
#debug concat(Inc_Name(), "\n")

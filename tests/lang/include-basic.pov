// checks #include of a helper file and use of what it declares
#version 3.7;
#include "inc/helper.inc"
#debug concat(str(Helper_Float, 0, 6), " ", vstr(3, Helper_Vector, ",", 0, 6), "\n")
#debug concat(Helper_String, " ", str(Helper_Double(21), 0, 0), "\n")

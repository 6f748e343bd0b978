// checks #include with a file name built from a string expression
#version 3.7;
#declare Dir = "inc/";
#declare Base = "helper";
#include concat(Dir, Base, ".inc")
#declare Name = "inc/counter.inc";
#declare Times = 10;
#include Name
#debug concat(Helper_String, " ", str(Times, 0, 0), "\n")

// checks a macro defined in an include that reads a local of the macro calling it
#version 3.7;
#include "inc/reader.inc"
#macro Caller()
  #local Shared_Name = "caller's local";
  Read_Shared()
#end
Caller()
#declare Shared_Name = "global";
Read_Shared()

// debug.inc: Debug_Message on and off, Debug, Warning (not in the #debug
// stream), and Debug_Inc_Stack with files that include nothing else.
#version 3.7;
#include "debug.inc"
#debug "start\n"
Debug_Message("on by default\n")
Set_Debug(true)
Debug_Message("shown\n")
Debug(true, "debug true\n")
Debug(false, "debug false\n")
Debug((1 < 2), "debug 1 < 2\n")
Warning(true, "warn true\n")
Warning(false, "warn false\n")
Error(false, "no error\n")
Set_Debug(false)
Debug_Message("after off\n")
Debug(true, "debug true with debugging off\n")
Set_Debug(on)
Debug_Message("on again\n")
Debug_Inc_Stack()
#include "colors.inc"
#include "consts.inc"
#include "strings.inc"
#include "arrays.inc"
#include "colors.inc"
#debug "end\n"

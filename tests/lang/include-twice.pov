// checks including the same file twice: its statements run again each time
#version 3.7;
#declare Times = 0;
#include "inc/counter.inc"
#include "inc/counter.inc"
#debug concat("Times=", str(Times, 0, 0), "\n")

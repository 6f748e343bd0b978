// checks #include inside a #for loop (the file is read on every iteration)
#version 3.7;
#declare Times = 0;
#for (I, 1, 3)
  #include "inc/counter.inc"
#end
#debug concat("Times=", str(Times, 0, 0), "\n")

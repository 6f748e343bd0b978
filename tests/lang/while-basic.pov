// checks a counting #while loop
#version 3.7;
#declare Count = 0;
#while (Count < 5)
  #debug concat("Count=", str(Count, 0, 0), "\n")
  #declare Count = Count + 1;
#end
#debug concat("after: ", str(Count, 0, 0), "\n")

// checks an array whose elements are only partly assigned, probed with #ifdef and defined()
#version 3.7;
#declare A = array[6];
#declare A[1] = 1;
#declare A[4] = 4;
#declare Count = 0;
#for (I, 0, 5)
  #if (defined(A[I])) #declare Count = Count + 1; #end
#end
#debug concat("assigned: ", str(Count, 0, 0), "\n")

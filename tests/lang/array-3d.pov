// checks a 3-D array filled in loops and summed
#version 3.7;
#declare A = array[2][3][4];
#for (I, 0, 1) #for (J, 0, 2) #for (K, 0, 3)
  #declare A[I][J][K] = I * 100 + J * 10 + K;
#end #end #end
#debug concat(str(A[1][2][3], 0, 0), " ", str(A[0][1][2], 0, 0), " ", str(A[1][0][0], 0, 0), "\n")
#declare S = 0;
#for (I, 0, 1) #for (J, 0, 2) #for (K, 0, 3) #declare S = S + A[I][J][K]; #end #end #end
#debug concat("sum=", str(S, 0, 0), "\n")

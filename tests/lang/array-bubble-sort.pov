// checks a bubble sort over a float array (loops, comparisons and element swaps)
#version 3.7;
#declare A = array[8] {5, 3, 8, -1, 7, 0.5, 3, 2};
#declare N = dimension_size(A, 1);
#for (I, 0, N - 2)
  #for (J, 0, N - 2 - I)
    #if (A[J] > A[J + 1])
      #declare T = A[J];
      #declare A[J] = A[J + 1];
      #declare A[J + 1] = T;
    #end
  #end
#end
#for (I, 0, N - 1) #debug concat(str(A[I], 0, 1), " ") #end
#debug "\n"

// checks passing a whole array to a macro that changes its elements
#version 3.7;
#macro Fill(Arr, Val)
  #for (I, 0, dimension_size(Arr, 1) - 1)
    #declare Arr[I] = Val * I;
  #end
#end
#declare A = array[5];
Fill(A, 3)
#for (I, 0, 4) #debug concat(str(A[I], 0, 0), " ") #end
#debug "\n"

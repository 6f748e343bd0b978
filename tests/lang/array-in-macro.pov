// checks arrays passed to macros, created in macros and returned through parameters
#version 3.7;
#macro Sum(Arr)
  #local S = 0;
  #for (I, 0, dimension_size(Arr, 1) - 1) #local S = S + Arr[I]; #end
  S
#end
#macro Range(N, Out)
  #declare Out = array[N];
  #for (I, 0, N - 1) #declare Out[I] = I + 1; #end
#end
#declare A = array[4] {1, 2, 3, 4};
#debug concat(str(Sum(A), 0, 0), "\n")
#declare R = 0;
Range(6, R)
#debug concat(str(dimension_size(R, 1), 0, 0), " ", str(Sum(R), 0, 0), "\n")

// checks a #local array inside a macro and a global array of the same name
#version 3.7;
#declare Arr = array[2] {1, 2};
#macro M()
  #local Arr = array[3] {7, 8, 9};
  #debug concat("local: ", str(dimension_size(Arr, 1), 0, 0), " ", str(Arr[2], 0, 0), "\n")
#end
M()
#debug concat("global: ", str(dimension_size(Arr, 1), 0, 0), " ", str(Arr[1], 0, 0), "\n")

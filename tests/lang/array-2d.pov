// checks a 2-D array with the manual's initialiser
#version 3.7;
#declare Digits =
array[4][10] {
  {7,6,7,0,2,1,6,5,5,0},
  {1,2,3,4,5,6,7,8,9,0},
  {0,9,8,7,6,5,4,3,2,1},
  {1,1,2,2,3,3,4,4,5,5}
  }
#for (R, 0, 3)
  #for (C, 0, 9) #debug str(Digits[R][C], 0, 0) #end
  #debug "\n"
#end
#debug concat(str(dimensions(Digits), 0, 0), " ", str(dimension_size(Digits, 1), 0, 0), " ", str(dimension_size(Digits, 2), 0, 0), "\n")

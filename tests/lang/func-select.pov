// checks select with three and four arguments (the manual's table)
#version 3.7;
#for (A, -2, 2)
  #debug concat("A=", str(A, 0, 0), " select4=", str(select(A, -1, 0, 1), 0, 0), " select3=", str(select(A, -1, 1), 0, 0), "\n")
#end
#debug concat(str(select(-0.5, 10, 20, 30), 0, 6), " ", str(select(0.5, 10, 20, 30), 0, 6), " ", str(select(0, 10, 20), 0, 6), "\n")

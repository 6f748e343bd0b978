// expect: 5:19: division by zero
// A loop expression compiled on its first runs still reports the error where it happens.
#declare I = 3;
#while (I > -3)
  #declare A = 10 / I;
  #declare I = I - 1;
#end

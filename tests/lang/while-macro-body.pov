// checks a #while loop whose body calls macros and declares globals
#version 3.7;
#macro Step(N) #declare Total = Total + N * N; #end
#declare Total = 0;
#declare I = 1;
#while (I <= 10)
  Step(I)
  #declare I = I + 1;
#end
#debug concat("sum of squares 1..10 = ", str(Total, 0, 0), "\n")

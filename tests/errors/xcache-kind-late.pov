// expect: 6:18: '+' needs numbers, vectors or colors, not a string
// An identifier that turns into a string mid-loop is caught by the ordinary parser.
#declare I = 0;
#declare S = 1;
#while (I < 5)
  #declare T = S + 1;
  #if (I = 2) #declare S = "x"; #end
  #declare I = I + 1;
#end

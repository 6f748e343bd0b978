// checks that an expression evaluated many times sees an identifier change kind
#version 3.7;
#declare A = 1;
#declare I = 0;
#while (I < 6)
  #if (I = 3) #declare A = <1, 2, 3>; #end
  #if (I = 4) #declare A = 7; #end
  #declare B = A * 2;
  #debug concat(str(I, 0, 0), ": ", vstr(3, B, ",", 0, 1), "\n")
  #declare I = I + 1;
#end

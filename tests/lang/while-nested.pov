// checks nested #while loops building a multiplication table
#version 3.7;
#declare I = 1;
#while (I <= 4)
  #declare J = 1;
  #while (J <= 4)
    #debug str(I*J, 3, 0)
    #declare J = J + 1;
  #end
  #debug "\n"
  #declare I = I + 1;
#end

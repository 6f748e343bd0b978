// expect: 3:1: #while is never closed by #end in its file
#declare I = 0;
#while (I < 3)
  #declare I = I + 1;

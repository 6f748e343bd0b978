// checks integer dice rolls made from rand()
#version 3.7;
#declare R = seed(6);
#for (I, 1, 40)
  #debug str(int(rand(R) * 6) + 1, 0, 0)
#end
#debug "\n"

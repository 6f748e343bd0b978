// checks that drawing from one stream does not disturb another
#version 3.7;
#declare R1 = seed(0);
#declare R2 = seed(12345);
#debug concat("R2 alone: ", str(rand(R2), 0, 8), " ", str(rand(R2), 0, 8), "\n")
#for (I, 1, 10) #declare Dummy = rand(R1); #end
#debug concat("R2 next:  ", str(rand(R2), 0, 8), " ", str(rand(R2), 0, 8), "\n")
#declare R3 = seed(12345);
#for (I, 1, 4) #debug concat(str(rand(R3), 0, 8), " ") #end
#debug "\n"

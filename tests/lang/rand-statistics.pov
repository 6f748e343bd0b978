// checks many draws: the mean, minimum, maximum and a histogram of 10 bins
#version 3.7;
#declare R = seed(2024);
#declare Bins = array[10] {0,0,0,0,0,0,0,0,0,0};
#declare Sum = 0;
#declare Lo = 1;
#declare Hi = 0;
#for (I, 1, 2000)
  #declare V = rand(R);
  #declare Sum = Sum + V;
  #declare Lo = min(Lo, V);
  #declare Hi = max(Hi, V);
  #declare B = min(int(V * 10), 9);
  #declare Bins[B] = Bins[B] + 1;
#end
#debug concat("mean=", str(Sum / 2000, 0, 8), " min=", str(Lo, 0, 8), " max=", str(Hi, 0, 8), "\n")
#for (I, 0, 9) #debug concat(str(Bins[I], 0, 0), " ") #end
#debug "\n"

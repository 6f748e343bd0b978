// expect: 9:9: rand() needs a stream made by seed(), not 8.9e+65
// As fuzz-rand-huge-stream.pov, in a loop, where the expression runs compiled
// (exprcache.c): it too cast the stream to long before checking its range.
#declare S = seed(1);
#declare K = 0;
#declare A = 0;
#for (I, 0, 3)
  #declare A = A +
    1 + rand(K);
  #declare K = 8.9e65;
#end

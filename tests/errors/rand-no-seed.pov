// expect: 2:14: rand() needs a stream made by seed(), not 7
#declare R = rand(7);

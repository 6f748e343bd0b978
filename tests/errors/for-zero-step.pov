// expect: 2:17: a #for step of 0 would never end
#for (I, 0, 10, 0) #end

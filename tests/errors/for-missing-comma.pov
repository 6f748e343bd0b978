// expect: 2:9: expected ',', found number 1
#for (I 1, 3) #end

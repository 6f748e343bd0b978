// checks #declare of a global array's elements from inside a macro
#version 3.7;
#declare Store = array[3];
#macro Put(I, V) #declare Store[I] = V; #end
Put(0, 10) Put(1, 20) Put(2, Store[0] + Store[1])
#debug concat(str(Store[0], 0, 0), " ", str(Store[1], 0, 0), " ", str(Store[2], 0, 0), "\n")

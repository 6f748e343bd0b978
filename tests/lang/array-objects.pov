// checks an array of objects and min/max extents of its elements
#version 3.7;
#declare Objs = array[3];
#for (I, 0, 2)
  #declare Objs[I] = sphere { <I * 3, 0, 0>, I + 1 }
#end
#for (I, 0, 2)
  #debug concat(vstr(3, min_extent(Objs[I]), ",", 0, 1), " ", vstr(3, max_extent(Objs[I]), ",", 0, 1), "\n")
#end

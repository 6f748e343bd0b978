// checks objects declared before and after #default, and min/max extents unaffected by textures
#version 3.7;
#declare My_Object = sphere { <0,0,0>, 1 }
#default { pigment { rgb 1 } }
#declare My_Thing = sphere { <0,0,0>, 2 texture {} }
#debug concat(vstr(3, max_extent(My_Object), ",", 0, 1), " ", vstr(3, max_extent(My_Thing), ",", 0, 1), "\n")

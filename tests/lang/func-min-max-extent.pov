// checks min_extent and max_extent of declared objects
#version 3.7;
#declare S = sphere { <1,2,3>, 2 }
#debug concat(vstr(3, min_extent(S), ",", 0, 6), " ", vstr(3, max_extent(S), ",", 0, 6), "\n")
#declare B = box { <-1,-2,-3>, <4,5,6> }
#debug concat(vstr(3, min_extent(B), ",", 0, 6), " ", vstr(3, max_extent(B), ",", 0, 6), "\n")
#declare B2 = box { 0, 1 scale <2,3,4> translate <1,1,1> }
#debug concat(vstr(3, min_extent(B2), ",", 0, 6), " ", vstr(3, max_extent(B2), ",", 0, 6), "\n")
#declare U = union { sphere { 0, 1 } box { <2,2,2>, <3,4,5> } }
#debug concat(vstr(3, min_extent(U), ",", 0, 6), " ", vstr(3, max_extent(U), ",", 0, 6), "\n")

// checks #declare placed in the middle of another statement (an object block)
#version 3.7;
#declare Here = <1, 2, 3>;
#declare Count = 0;
#declare Rod = cylinder { -5*x, 5*x, 1 }
#declare U = union {
  object { Rod translate Here*Count }
  #declare Count = Count + 1;
  object { Rod translate Here*Count }
  #declare Count = Count + 1;
  object { Rod translate Here*Count }
}
#debug concat("Count=", str(Count, 0, 0), "\n")
#debug concat(vstr(3, max_extent(U), ",", 0, 6), "\n")

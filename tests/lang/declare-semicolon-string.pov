// checks that string and object declarations need no semicolon but may have one
#version 3.7;
#declare A = "no semicolon"
#declare B = "with semicolon";
#declare O = sphere { 0, 1 }
#declare P = sphere { 0, 2 };
#debug concat(A, "|", B, "\n")
#debug concat(vstr(3, max_extent(P), ",", 0, 1), "\n")

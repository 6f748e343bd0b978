// checks redeclaring a vector identifier to a float and back
#version 3.7;
#declare V = <1,2,3>;
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#declare V = 5;
#debug concat(str(V, 0, 6), "\n")
#declare V = <4,5>;
#debug concat(vstr(2, V, ",", 0, 6), "\n")
#declare V = V + 1;
#debug concat(vstr(2, V, ",", 0, 6), "\n")

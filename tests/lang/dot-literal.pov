// checks a dot item directly after a vector literal and a parenthesised expression
#version 3.7;
#declare V = <1,2,3>;
#debug concat(str(<4,5,6>.y, 0, 6), "\n")
#debug concat(str((V+1).z, 0, 6), "\n")
#debug concat(str((V*<2,3,4>).y, 0, 6), "\n")
#debug concat(str(V . x, 0, 6), "\n")

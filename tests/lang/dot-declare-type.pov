// checks that declaring from a dot item yields a float usable with str()
#version 3.7;
#declare V = <9, 8, 7>;
#declare A = V.x;
#declare B = V.y + V.z;
#debug concat(str(A, 0, 6), " ", str(B, 0, 6), "\n")
#declare C = rgb <0.5, 0.25, 1>;
#declare G = C.green;
#debug concat(str(G * 4, 0, 6), "\n")

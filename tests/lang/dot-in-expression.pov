// checks dot items combined in arithmetic, comparisons and vector literals
#version 3.7;
#declare P = <3, 4, 12>;
#declare Len = sqrt(P.x*P.x + P.y*P.y + P.z*P.z);
#debug concat(str(Len, 0, 6), "\n")
#debug concat(str((P.x < P.y), 0, 6), " ", str((P.z = 12), 0, 6), "\n")
#declare Q = <P.z, P.x, P.y> * 2;
#debug concat(vstr(3, Q, ",", 0, 6), "\n")

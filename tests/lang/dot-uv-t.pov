// checks .u .v on 2D vectors and .t on 4D vectors
#version 3.7;
#declare UV = <0.25, 0.75>;
#declare Q = <1, 2, 3, 4>;
#debug concat(str(UV.u, 0, 6), " ", str(UV.v, 0, 6), "\n")
#debug concat(str(Q.t, 0, 6), "\n")
#debug concat(str(x.x, 0, 6), str(y.y, 0, 6), str(t.t, 0, 6), str(u.u, 0, 6), str(v.v, 0, 6), "\n")
#declare V3 = <5,6,7>;
#debug concat(str(V3.u, 0, 6), " ", str(V3.v, 0, 6), "\n")

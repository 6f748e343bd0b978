// checks colour dot items on plain vectors and vector dot items on colours
#version 3.7;
#declare V = <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat(str(V.red, 0, 6), " ", str(V.green, 0, 6), " ", str(V.blue, 0, 6), " ", str(V.filter, 0, 6), " ", str(V.transmit, 0, 6), "\n")
#declare C = rgbt <0.6, 0.7, 0.8, 0.9>;
#debug concat(str(C.x, 0, 6), " ", str(C.y, 0, 6), " ", str(C.z, 0, 6), " ", str(C.t, 0, 6), "\n")
#debug concat(str(C.u, 0, 6), " ", str(C.v, 0, 6), "\n")

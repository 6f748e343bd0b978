// checks vdot and vlength
#version 3.7;
#debug concat(str(vdot(<1,2,3>, <4,5,6>), 0, 6), " ", str(vdot(x, y), 0, 6), " ", str(vdot(<1,1,1>, -1), 0, 6), "\n")
#debug concat(str(vlength(<3,4,0>), 0, 6), " ", str(vlength(<1,1,1>), 0, 6), " ", str(vlength(0), 0, 6), " ", str(vlength(<-2,0,0>), 0, 6), "\n")
#declare V1 = <1,2,3>; #declare V2 = <4,6,3>;
#debug concat(str(vlength(V2-V1), 0, 6), "\n")
#debug concat(str(vdot(<1,2>, <3,4>), 0, 6), "\n")

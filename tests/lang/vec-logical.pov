// checks logical operators and ! on vectors, component by component
#version 3.7;
#declare A = (<1,0,1> & <1,1,0>);
#debug concat(vstr(3, A, ",", 0, 6), "\n")
#declare B = (<1,0,0> | <0,0,1>);
#debug concat(vstr(3, B, ",", 0, 6), "\n")
#declare C = !<1,0,2>;
#debug concat(vstr(3, C, ",", 0, 6), "\n")

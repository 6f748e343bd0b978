// expect: 2:24: division by zero
#declare V = <1, 2, 3> / <1, 0, 1>;

// expect: 3:9: a plane's normal cannot be the zero vector
#declare N = <1, 2, 3>;
plane { N - N, 1 }

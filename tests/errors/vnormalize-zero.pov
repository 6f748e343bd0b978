// expect: 2:14: vnormalize() of a zero-length vector
#declare V = vnormalize(<0, 0, 0>);

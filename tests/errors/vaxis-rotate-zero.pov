// expect: 2:14: vaxis_rotate() about a zero-length axis
#declare V = vaxis_rotate(<1, 2, 3>, <0, 0, 0>, 90);

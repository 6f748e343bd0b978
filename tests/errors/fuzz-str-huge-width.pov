// expect: 7:1: #error: done
// Found by fuzzing (UBSan): str() and vstr() converted a huge width, precision or
// component count to int (undefined behaviour); they saturate now. make check-sanitize
// would stop before the #error if they did not.
#declare A = concat(str(1, 1e80, -1e80), vstr(1e80, <1,2,3>, ",", -2.2e73, 1e300));
#declare B = vstr(3, <1,2,3>, ",", 0, 2.22222e+73);
#error "done"

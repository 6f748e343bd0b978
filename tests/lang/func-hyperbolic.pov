// checks sinh cosh tanh and their inverses asinh acosh atanh
#version 3.7;
#debug concat(str(sinh(0), 0, 6), " ", str(sinh(1), 0, 6), " ", str(sinh(-2), 0, 6), "\n")
#debug concat(str(cosh(0), 0, 6), " ", str(cosh(1), 0, 6), " ", str(cosh(-2), 0, 6), "\n")
#debug concat(str(tanh(0), 0, 6), " ", str(tanh(1), 0, 6), " ", str(tanh(-2), 0, 6), "\n")
#debug concat(str(asinh(0), 0, 6), " ", str(asinh(1), 0, 6), " ", str(asinh(-2), 0, 6), "\n")
#debug concat(str(acosh(1), 0, 6), " ", str(acosh(2), 0, 6), " ", str(acosh(10), 0, 6), "\n")
#debug concat(str(atanh(0), 0, 6), " ", str(atanh(0.5), 0, 6), " ", str(atanh(-0.9), 0, 6), "\n")
#debug concat(str(asinh(sinh(1.25)), 0, 6), " ", str(acosh(cosh(1.25)), 0, 6), " ", str(atanh(tanh(0.25)), 0, 6), "\n")

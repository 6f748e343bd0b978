// checks exp ln log (log is base 10)
#version 3.7;
#debug concat(str(exp(0), 0, 6), " ", str(exp(1), 0, 6), " ", str(exp(-1), 0, 6), " ", str(exp(2.5), 0, 6), "\n")
#debug concat(str(ln(1), 0, 6), " ", str(ln(exp(2)), 0, 6), " ", str(ln(10), 0, 6), " ", str(ln(0.5), 0, 6), "\n")
#debug concat(str(log(1), 0, 6), " ", str(log(10), 0, 6), " ", str(log(1000), 0, 6), " ", str(log(0.01), 0, 6), " ", str(log(2), 0, 6), "\n")

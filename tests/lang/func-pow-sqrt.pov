// checks pow and sqrt including fractional and negative exponents
#version 3.7;
#debug concat(str(pow(2, 10), 0, 6), " ", str(pow(2, 0.5), 0, 6), " ", str(pow(2, -2), 0, 6), " ", str(pow(-2, 3), 0, 6), " ", str(pow(0, 2), 0, 6), " ", str(pow(10, 0), 0, 6), "\n")
#debug concat(str(sqrt(0), 0, 6), " ", str(sqrt(2), 0, 6), " ", str(sqrt(16), 0, 6), " ", str(sqrt(0.25), 0, 6), " ", str(sqrt(1e10), 0, 6), "\n")
#debug concat(str(pow(-8, 2), 0, 6), " ", str(pow(1.5, 2.5), 0, 6), "\n")

// checks comparisons that only succeed because of the 1e-10 tolerance
#version 3.7;
#debug concat(str((1/3*3 = 1), 0, 0), str((0.1*3 = 0.3), 0, 0), str((sqrt(2)*sqrt(2) = 2), 0, 0), "\n")
#debug concat(str((1/3*3 != 1), 0, 0), str((sin(pi) = 0), 0, 0), str((cos(pi/2) > 0), 0, 0), "\n")
#debug concat(str((1e-9 = 0), 0, 0), str((1e-10 = 0), 0, 0), str((5e-11 = 0), 0, 0), "\n")

// checks the conditional operator ?: with floats
#version 3.7;
#declare A = 5;
#debug concat(str((A > 3 ? 10 : 20), 0, 6), "\n")
#debug concat(str((A < 3 ? 10 : 20), 0, 6), "\n")
#debug concat(str((0 ? 1 : 2), 0, 6), "\n")
#debug concat(str((0.5 ? 1 : 2), 0, 6), "\n")
#debug concat(str((-1 ? 1 : 2), 0, 6), "\n")
#debug concat(str((1 ? 2+3 : 4*5), 0, 6), "\n")
#debug concat(str((1e-12 ? 1 : 2), 0, 6), "\n")

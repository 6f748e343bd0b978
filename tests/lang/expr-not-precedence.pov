// checks that ! binds tighter than * and +
#version 3.7;
#debug concat(str(!0*5, 0, 6), "\n")
#debug concat(str(!1+1, 0, 6), "\n")
#debug concat(str(!(1+1), 0, 6), "\n")
#debug concat(str(-!0, 0, 6), "\n")
#debug concat(str(!-0, 0, 6), "\n")
#debug concat(str(3-!0, 0, 6), "\n")

// checks deeply nested parentheses
#version 3.7;
#debug concat(str(((((1)))), 0, 6), "\n")
#debug concat(str((((1+2)*(3+4))-((5-6)*(7-8))), 0, 6), "\n")
#debug concat(str(-(-(-(1))), 0, 6), "\n")
#debug concat(str(2*(3*(4*(5+1))), 0, 6), "\n")

// checks left associativity when * and / (or + and -) are mixed
#version 3.7;
#debug concat(str(2*3/4*5, 0, 6), "\n")
#debug concat(str(1-2+3-4, 0, 6), "\n")
#debug concat(str(100/10/5*2, 0, 6), "\n")
#debug concat(str(1/2/2/2, 0, 6), "\n")
#debug concat(str(10-5-3+1-1, 0, 6), "\n")

// checks that * and / bind tighter than + and -
#version 3.7;
#debug concat("1+2*3=", str(1+2*3, 0, 6), "\n")
#debug concat("(1+2)*3=", str((1+2)*3, 0, 6), "\n")
#debug concat("10-4/2=", str(10-4/2, 0, 6), "\n")
#debug concat("2*3+4*5=", str(2*3+4*5, 0, 6), "\n")
#debug concat("8/2-6/3=", str(8/2-6/3, 0, 6), "\n")
#debug concat("1+2*3-4/2+1=", str(1+2*3-4/2+1, 0, 6), "\n")
#debug concat("((2+3)*(4-1))/5=", str(((2+3)*(4-1))/5, 0, 6), "\n")

// checks float multiplication and division, including left associativity
#version 3.7;
#debug concat("2*3*4=", str(2*3*4, 0, 6), "\n")
#debug concat("24/4/2=", str(24/4/2, 0, 6), "\n")
#debug concat("24/(4/2)=", str(24/(4/2), 0, 6), "\n")
#debug concat("1/3=", str(1/3, 0, 6), "\n")
#debug concat("2/3*3=", str(2/3*3, 0, 6), "\n")
#debug concat("7/2=", str(7/2, 0, 6), "\n")
#debug concat("-7/2=", str(-7/2, 0, 6), "\n")
#debug concat("0.5*0.5=", str(0.5*0.5, 0, 6), "\n")

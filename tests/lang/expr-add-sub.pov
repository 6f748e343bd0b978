// checks float addition and subtraction, including left associativity
#version 3.7;
#debug concat("1+2+3=", str(1+2+3, 0, 6), "\n")
#debug concat("10-3-2=", str(10-3-2, 0, 6), "\n")
#debug concat("10-(3-2)=", str(10-(3-2), 0, 6), "\n")
#debug concat("1.5+2.25=", str(1.5+2.25, 0, 6), "\n")
#debug concat("0.1+0.2=", str(0.1+0.2, 0, 6), "\n")
#debug concat("-1-1=", str(-1-1, 0, 6), "\n")
#debug concat("5-10+3=", str(5-10+3, 0, 6), "\n")

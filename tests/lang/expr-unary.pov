// checks unary minus, unary plus and their binding relative to binary operators
#version 3.7;
#debug concat("-3=", str(-3, 0, 6), "\n")
#debug concat("+3=", str(+3, 0, 6), "\n")
#debug concat("--3=", str(--3, 0, 6), "\n")
#debug concat("-+-3=", str(-+-3, 0, 6), "\n")
#debug concat("2*-3=", str(2*-3, 0, 6), "\n")
#debug concat("-2*-3=", str(-2*-3, 0, 6), "\n")
#debug concat("5--3=", str(5--3, 0, 6), "\n")
#debug concat("5- -3=", str(5- -3, 0, 6), "\n")
#debug concat("5+-3=", str(5+-3, 0, 6), "\n")
#debug concat("-(2+3)=", str(-(2+3), 0, 6), "\n")
#debug concat("6/-2=", str(6/-2, 0, 6), "\n")

// checks that relational operators chain left to right (result 0/1 is compared again)
#version 3.7;
#debug concat("(3>2>1)=", str((3>2>1), 0, 6), "\n")
#debug concat("(1<2<3)=", str((1<2<3), 0, 6), "\n")
#debug concat("(2<3<1)=", str((2<3<1), 0, 6), "\n")
#debug concat("(5=5=1)=", str((5=5=1), 0, 6), "\n")
#debug concat("(0<1=1)=", str((0<1=1), 0, 6), "\n")

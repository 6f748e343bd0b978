// checks that arithmetic binds tighter than relational operators
#version 3.7;
#debug concat("(1+1=2)=", str((1+1=2), 0, 6), "\n")
#debug concat("(2*3>5)=", str((2*3>5), 0, 6), "\n")
#debug concat("(10/2<=4+1)=", str((10/2<=4+1), 0, 6), "\n")
#debug concat("(1-3>=-2)=", str((1-3>=-2), 0, 6), "\n")
#debug concat("((1<2)+(3<4))=", str(((1<2)+(3<4)), 0, 6), "\n")
#debug concat("((1<2)*5)=", str(((1<2)*5), 0, 6), "\n")

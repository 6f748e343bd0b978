// checks ceil floor int on positive, negative, integer and half values
#version 3.7;
#macro Row(A) #debug concat(str(A, 0, 2), ": ceil=", str(ceil(A), 0, 1), " floor=", str(floor(A), 0, 1), " int=", str(int(A), 0, 1), "\n") #end
Row(2.5) Row(-2.5) Row(2) Row(-2) Row(0.1) Row(-0.1) Row(2.9999) Row(-2.9999) Row(0) Row(1e6+0.5)

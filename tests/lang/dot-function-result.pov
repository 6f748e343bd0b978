// checks a dot item after a built-in vector function, a macro call and an array element
#version 3.7;
#debug concat(str(vnormalize(<0,3,4>).z, 0, 6), "\n")
#debug concat(str(vcross(x, y).z, 0, 6), "\n")
#declare A = array[2] {<1,2,3>, <4,5,6>};
#debug concat(str(A[1].y, 0, 6), "\n")
#macro M() <7,8,9> #end
#debug concat(str(M().z, 0, 6), "\n")

// An array declared without initialiser and without ';', followed at once
// by a directive that assigns its elements (as in a scene building an
// array in a loop). (Found writing the arrays.inc tests.)
#version 3.7;
#declare A = array[3]
#declare A[1] = 2;
#declare B = array[2][2]
#for (I, 0, 1) #for (J, 0, 1) #declare B[I][J] = I * 10 + J; #end #end
#local C = array[2]
#declare C[0] = "x";
#debug concat(str(A[1], 0, 0), " ", str(B[1][0], 0, 0), " ", str(B[0][1], 0, 0), " ", C[0], "\n")

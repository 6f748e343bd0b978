// expect: 3:14: expected ';' after the value of 'A': POV-Ray needs it for floats, vectors and colors
#version 3.7;
#declare A = 1
#declare B = A;

// expect: 4:10: 'T' is a pigment, not an object
#version 3.7;
#declare T = array[1] { pigment { rgb 1 } }
object { T[0] }

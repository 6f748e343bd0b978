// expect: 4:10: element of array 'O' used before it was given a value
#version 3.7;
#declare O = array[2];
object { O[1] }

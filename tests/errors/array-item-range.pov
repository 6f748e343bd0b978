// expect: 4:12: index 2 is out of range for dimension 1 of array 'O' (size 2)
#version 3.7;
#declare O = array[2] { sphere { 0, 1 }, box { 0, 1 } }
object { O[1 + 1] }

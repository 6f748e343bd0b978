// expect: 5:1: expected an object modifier or '}', found end of file
#version 3.7;
sphere { <0, 0, 0>, 1


// checks concat() with one, two and many arguments, and nested concat
#version 3.7;
#debug concat("single\n")
#debug concat("a", "b", "\n")
#debug concat("a", "b", "c", "d", "e", "f", "g", "\n")
#debug concat(concat("x", "y"), concat("", "z"), "\n")
#declare A = 12.34321;
#debug concat("Value is ", str(A,3,1), " inches\n")
#declare Name = "John";
#declare Name = concat(Name, " Doe");
#debug concat(Name, "\n")
#debug concat("", "", "empty parts\n")

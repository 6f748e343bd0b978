// checks array initialisers nested in arrays declared with array[] inside braces
#version 3.7;
#declare Nest = array[2] { array[2] {1, 2}, array[3] {"a", "b", "c"} }
#declare First = Nest[0];
#declare Second = Nest[1];
#debug concat(str(First[1], 0, 0), " ", Second[2], "\n")

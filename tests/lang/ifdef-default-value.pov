// checks the idiom of giving an identifier a default value only if it is not declared
#version 3.7;
#declare Given = 5;
#ifndef (Given) #declare Given = 1; #end
#ifndef (Missing) #declare Missing = 2; #end
#debug concat(str(Given, 0, 0), " ", str(Missing, 0, 0), "\n")

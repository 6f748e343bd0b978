// checks the manual's warning: a macro body without outer parentheses is pasted as tokens
#version 3.7;
#macro Bad(A, B) A + B #end
#macro Good(A, B) (A + B) #end
#debug concat(str(Bad(1, 2) * 10, 0, 6), " ", str(Good(1, 2) * 10, 0, 6), "\n")

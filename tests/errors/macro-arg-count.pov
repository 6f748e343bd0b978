// expect: 3:1: macro M takes 2 arguments, but 1 was given
#macro M(A, B) A + B #end
M(1)

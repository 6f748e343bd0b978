// expect: 2:13: macro M has two parameters named 'A'
#macro M(A, A) #end

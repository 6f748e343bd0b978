// expect: 3:15: expected '(' after the macro name, found ';'
#macro M() 1 #end
#declare A = M;

// expect: 3:1: #end without an open #if, #ifdef, #ifndef, #switch, #while, #for or #macro
#declare A = 1;
#end

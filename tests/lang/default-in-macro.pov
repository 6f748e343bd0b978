// checks #default inside a macro and inside a loop (directives work anywhere)
#version 3.7;
#macro Set_Default(C) #default { pigment { rgb C } } #end
#for (I, 1, 3)
  Set_Default(<I/3, 0, 0>)
#end
#debug concat("ran ", str(I - 1, 0, 0), " times\n")

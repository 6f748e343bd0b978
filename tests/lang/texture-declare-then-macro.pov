// checks a texture #declared without ';' right before a macro call that uses it
#version 3.7;
#macro M(T) #debug "called\n" sphere { 0, 1 texture { T } } #end
#declare B = texture { pigment { rgb 1 } }
M(B)
#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt <1, 0, 0, 0.5> } }
M(L)
#debug "done\n"

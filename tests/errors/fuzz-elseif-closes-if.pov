// expect: 5:1: the operands of #elseif closed the #if they belong to (a directive among them)
// As fuzz-range-closes-switch.pov, with the #end among an #elseif's operands:
// the #if's own #end then closed one block too many.
#if (0)
#elseif (#end 0)
#end
#for (I, 1, 1) #end

// expect: 6:14: macro M was redefined or undefined while the arguments of its call were read
// The same as fuzz-macro-redefined-in-args.pov with #undef: the macro
// being called is freed by its own arguments.
#version 3.7;
#macro M(A) (A + 1) #end
#declare X = M(#undef M 2);

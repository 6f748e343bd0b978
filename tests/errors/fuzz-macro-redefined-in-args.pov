// expect: 7:14: macro M was redefined or undefined while the arguments of its call were read
// Found by fuzz_parse: a #macro among a call's arguments replaced the
// macro being called, which was freed while the call still used it
// (heap-use-after-free). POV-Ray 3.7 rejects this scene too.
#version 3.7;
#macro M(A) (A + 1) #end
#declare X = M(
#macro M(B) (B * 10) #end
2);

// checks vturbulence's octaves outside 1..10: POV-Ray 3.7 computes 1 octave for
// 0, -5 and 1e30 (its int cast of 1e30 is negative) and 10 for 11, 100 and
// 2e9 (the expected output is POV-Ray's). lucent cast 1e30 to int undefinedly,
// gave 0 for 0 octaves, and ran 2e9 octaves for minutes (to a NaN).
#version 3.7;
#macro P(O) #debug concat(vstr(3, vturbulence(2, 0.5, O, <0.3,0.2,0.1>), ",", 0, 6), "\n") #end
P(1) P(0) P(-5) P(1e30)
P(10) P(11) P(100) P(2e9)

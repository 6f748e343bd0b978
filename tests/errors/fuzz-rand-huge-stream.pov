// expect: 6:14: rand() needs a stream made by seed(), not 8.88889e+65
// Found by fuzz_parse: rand() cast its stream number to long before
// checking its range, undefined for 8.9e65 (UBSan); it is checked as a
// float first now.
#version 3.7;
#declare X = rand(888888888888888888888888888888888888888888888888888888888888888888);

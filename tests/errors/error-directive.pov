// expect: 3:1: #error: stop here
#declare A = 1;
#error "stop here"
sphere { 0, A }

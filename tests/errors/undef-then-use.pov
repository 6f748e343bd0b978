// expect: 4:13: undefined identifier 'R'
#declare R = 1;
#undef R
sphere { 0, R }

// expect: 3:13: undefined identifier 'Radus'; did you mean 'Radius'?
#declare Radius = 1;
sphere { 0, Radus }

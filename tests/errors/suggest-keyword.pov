// expect: 2:1: undefined identifier 'Sphere'; did you mean the keyword 'sphere'?
Sphere { 0, 1 }

// expect: 2:20: expected ',', found number 1
sphere { <0, 0, 0> 1 }

// expect: 2:15: unexpected character '@'
sphere { 0, 1 @ }

// expect: 3:1: unterminated comment: '/*' is never closed by '*/'
sphere { 0, 1 }
/* /* nested */ still open
sphere { 0, 2 }

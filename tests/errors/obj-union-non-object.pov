// expect: 2:25: expected an object, an object modifier or '}', found number 5
union { sphere { 0, 1 } 5 }

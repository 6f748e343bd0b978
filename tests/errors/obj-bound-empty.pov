// expect: 2:15: expected an object in bounded_by
sphere { 0, 1 bounded_by { } }

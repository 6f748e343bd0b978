// expect: 2:15: expected an object in clipped_by
sphere { 0, 1 clipped_by { } }

// expect: 2:25: expected a transform identifier, found number 5
sphere { 0, 1 transform 5 }

// expect: 2:27: expected a transformation, a transform identifier, inverse or '}', found number 5
sphere { 0, 1 transform { 5 } }

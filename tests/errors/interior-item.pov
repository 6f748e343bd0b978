// expect: 2:26: expected an interior item or '}', found 'phong'
sphere { 0, 1 interior { phong 1 } }

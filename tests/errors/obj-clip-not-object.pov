// expect: 2:28: expected an object or '}', found 'pigment'
sphere { 0, 1 clipped_by { pigment { rgb 1 } } }

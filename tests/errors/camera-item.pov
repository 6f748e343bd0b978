// expect: 2:30: expected a camera item or '}', found 'radius'
camera { location <0, 1, -5> radius 3 }

// expect: 2:19: a cylinder camera's type must be 1, 2, 3 or 4, not 5
camera { cylinder 5 location <0, 1, -5> }

// expect: 2:37: look_at points along both the sky and the right vector
camera { location <0, 0, 0> right y look_at <0, 3, 0> }

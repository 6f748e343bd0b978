// expect: 2:29: look_at cannot be the camera's own location
camera { location <0, 0, 0> look_at <0, 0, 0> }

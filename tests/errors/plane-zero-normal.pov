// expect: 2:9: a plane's normal cannot be the zero vector
plane { <0, 0, 0>, 1 }

// expect: 2:31: a camera's angle cannot be negative (-90)
camera { spherical angle 360, -90 }

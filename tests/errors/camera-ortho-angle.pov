// expect: 2:49: an orthographic camera's angle must be less than 180 degrees, not 190
camera { orthographic location <0, 1, -5> angle 190 }

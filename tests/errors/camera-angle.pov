// expect: 2:46: a perspective camera's angle must be less than 180 degrees, not 190
camera { location <0, 0, -5> look_at 0 angle 190 }

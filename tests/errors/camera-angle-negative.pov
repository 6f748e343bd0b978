// expect: 2:24: a camera's angle cannot be negative (-30)
camera { fisheye angle -30 }

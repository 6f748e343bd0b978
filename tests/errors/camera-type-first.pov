// expect: 2:30: the camera type (fisheye) must come first in the camera block
camera { location <0, 1, -5> fisheye }

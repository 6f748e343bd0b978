// expect: 2:40: cannot read image file "../data/images/make.py"
plane { z, 0 pigment { image_map { png "../data/images/make.py" } } }

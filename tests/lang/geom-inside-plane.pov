// geom-inside-plane.pov: inside() of points on and near a plane's surface
// of other shapes (the expected output is what POV-Ray 3.7.0.10 prints: a
// plane's surface and up to 1e-10 beyond it is inside). Box faces are left
// out: POV-Ray counts them inside, lucent outside, which keeps a difference
// with a zero-thickness box from cutting anything (tests/stability).
#version 3.7;
#macro I(S, O, P) #debug concat(S, " ", str(inside(O, P), 0, 0), "\n") #end
I("plane", plane { y, 0 }, <0, 0, 0>)
I("plane1", plane { y, 1 }, <3, 1, 2>)
I("planeneg", plane { -y, 0.5 }, <3, -0.5, 2>)
I("p+1e-7", plane { y, 0 }, <0, 1e-7, 0>)
I("p+1e-9", plane { y, 0 }, <0, 1e-9, 0>)
I("p+1e-11", plane { y, 0 }, <0, 1e-11, 0>)
I("prot", plane { y, 0 rotate x*30 }, vrotate(<0, 0, 1>, x*30))
I("sphere", sphere { 0, 1 }, <1, 0, 0>)
I("torus", torus { 1, 0.5 }, <1.5, 0, 0>)
I("quadric", quadric { <1, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }, <1, 0, 0>)

// vrotate and vaxis_rotate to the last bit: POV-Ray computes the sines and
// cosines of right angles as they come (cos(90 degrees) = 6.12e-17), so
// turned vectors keep those tiny values, and vaxis_rotate builds its
// rotation matrix before applying it.
#version 3.7;
#macro P(V) #debug concat(vstr(3, V, ",", 0, 20), "\n") #end
P(vrotate(<1,2,3>, <0,0,90>))
P(vrotate(<1,2,3>, <90,0,0>))
P(vrotate(<1,2,3>, <0,90,0>))
P(vrotate(<1,2,3>, <30,45,180>))
P(vrotate(<1,0,0>, <0,180,0>))
P(vrotate(<0.3,-1.7,2.2>, <-270,12.5,720>))
P(vrotate(<1,0,0>, <0,0,0>))
P(vaxis_rotate(<1,2,3>, <0,0,1>, 90))
P(vaxis_rotate(<1,2,3>, <1,1,1>, 120))
P(vaxis_rotate(<1,2,3>, <0.2,-0.5,3>, -37.5))
P(vaxis_rotate(<1,0,0>, y, 180))
P(vaxis_rotate(<4,5,6>, <0,2,0>, 90))

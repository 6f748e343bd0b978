// checks a transform function (a vector-valued function of three arguments)
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#declare foo = function {
  transform {
    rotate <90, 0, 0>
    scale 4
  }
}
#declare myvector = foo(4, 3, 7);
#debug concat(V3(myvector), "\n")
#declare T2 = function { transform { translate <1, 2, 3> scale 2 } }
#debug concat(V3(T2(1, 1, 1)), "\n")

// checks trace() hit points and normals, and the zero normal on a miss
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#declare MySphere = sphere { <0, 0, 0>, 1 }
#declare Norm = <0, 0, 0>;
#declare Start = <1, 1, 1>;
#declare Inter = trace(MySphere, Start, <0, 0, 0>-Start, Norm);
#debug concat(V3(Inter), " ", V3(Norm), "\n")
#declare Inter = trace(MySphere, <0, 0, -5>, z, Norm);
#debug concat(V3(Inter), " ", V3(Norm), "\n")
#declare Inter = trace(MySphere, <5, 5, -5>, z, Norm);
#debug concat(V3(Inter), " ", V3(Norm), " ", str((vlength(Norm) != 0), 0, 0), "\n")
#declare MyBox = box { <-1,-1,-1>, <1,1,1> }
#declare Inter = trace(MyBox, <0.5, 10, 0.25>, -y);
#debug concat(V3(Inter), "\n")

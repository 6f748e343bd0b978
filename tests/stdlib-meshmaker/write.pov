// write.pov: meshmaker.inc's mesh files. tests/stdlib.sh runs this twice
// in an empty folder: the first run writes a Lathe (turned through right
// angles, whose tiny sines the files keep), a Coons patch and a mesh from
// BuildWriteMesh2 in the four formats (.pcm, .arr, .obj, and a mesh2
// statement for any other name; the extension in any case); the second
// finds the files there: it reads the mesh2 file back and leaves the
// others alone. The files and the #debug stream of both runs must be byte
// for byte what POV-Ray 3.7 writes with its own meshmaker.inc (stored
// beside this scene, recorded with tests/stdlib-meshmaker/record.sh).
#version 3.7;
#include "meshmaker.inc"
#declare S = spline { cubic_spline -0.5, <0.2, -0.5, 0>, 0, <0.5, 0, 0>, 0.5, <1, 0.5, 0>, 1, <0.5, 1, 0>, 1.5, <0.2, 1.5, 0> }
#declare M1 = Lathe(S, 2, 270, 3, "lathe.pcm")
#declare M2 = Lathe(S, 2, 270, 3, "lathe.arr")
#declare M3 = Lathe(S, 2, 270, 3, "lathe.obj")
#declare M4 = Lathe(S, 2, 270, 3, "lathe.inc")
#declare S1 = spline { linear_spline 0, <0,0,0>, 1, <1,0,0> }
#declare S2 = spline { linear_spline 0, <1,0,0>, 1, <1,0,1> }
#declare S3 = spline { linear_spline 0, <1,0,1>, 1, <0,1,1> }
#declare S4 = spline { linear_spline 0, <0,1,1>, 1, <0,0,0> }
#declare M5 = Coons(S1, S2, S3, S4, 4, 3, "coons.PCM")
#declare M6 = Coons(S1, S2, S3, S4, 4, 3, "coons.Arr")
#declare VA = array[6] { <0,0,0>, <1,0,0>, <2,0.5,0>, <0,1,0>, <1,1,0.25>, <2,1.5,1/3> }
#declare NA = array[6] { <0,0,1>, <0,0,1>, <-0.1,0,1>, <0,0,1>, <0,0.2,1>, <0,0,1> }
#declare UA = array[6] { <0,0>, <0.5,0>, <1,0>, <0,1>, <0.5,1>, <1,1> }
#declare M7 = BuildWriteMesh2(VA, NA, UA, 2, 1, "grid.obj")
#declare M8 = BuildWriteMesh2(VA, NA, UA, 2, 1, "grid")
#declare M9 = BuildWriteMesh2(VA, NA, UA, 2, 1, "")
#debug concat("CheckFileName: ", str(CheckFileName(""), 0, 0), " ", str(CheckFileName("lathe.pcm"), 0, 0), " ",
	str(CheckFileName("lathe.inc"), 0, 0), " ", str(CheckFileName("no.obj"), 0, 0), " ", str(CheckFileName("no.PCM"), 0, 0), " ",
	str(CheckFileName("no.arr"), 0, 0), " ", str(CheckFileName("no.inc"), 0, 0), "\n")
#macro E(Name, O)
	#debug concat(Name, ": ", vstr(3, min_extent(O), ",", 0, 4), " / ", vstr(3, max_extent(O), ",", 0, 4), "\n")
#end
E("lathe", M4)
E("grid", M8)

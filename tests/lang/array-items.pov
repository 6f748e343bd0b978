// checks array elements where an item identifier stands: object { O[i] },
// texture { T[i] }, pigment { P[i] }, finish { F[i] }, an element of an
// element array, and an element followed by modifiers.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare O = array[2] { sphere { 0, 1 }, box { <0, 0, 0>, <1, 2, 3> } }
#declare P = array[2] { pigment { rgb <1, 0, 0> }, pigment { rgb <0.2, 0.4, 0.6> } }
#declare T = array[2] {
  texture { pigment { rgb <0, 1, 0> } },
  texture { pigment { rgb <0.5, 0.25, 0.125> } }
}
#declare F = array[1] { finish { ambient 0.3 } }
#declare G = array[2][2] { { 0, 1 }, { 2, 3 } }
#declare Nest = array[2] { array[2] { pigment { rgb 0.1 }, pigment { rgb 0.7 } }, O }
#declare I = 1;
#declare A = object { O[I] scale 2 translate x }
#debug concat(vstr(3, min_extent(A), ",", 0, 2), " ", vstr(3, max_extent(A), ",", 0, 2), "\n")
#declare B = object { Nest[1][0] }
#debug concat(vstr(3, max_extent(B), ",", 0, 2), "\n")
#declare FP = function { pigment { P[G[0][1]] } }
#debug concat(vstr(3, FP(0, 0, 0), ",", 0, 3), "\n")
#declare FN = function { pigment { Nest[0][1] } }
#debug concat(vstr(3, FN(0, 0, 0), ",", 0, 3), "\n")
#declare FT = function { pigment { gradient x pigment_map { [0 P[0]] [1 P[1]] } } }
#debug concat(vstr(3, FT(0.5, 0, 0), ",", 0, 3), "\n")
#declare S = sphere { 0, 1 texture { T[1] finish { F[0] } } }
#declare S2 = sphere { 0, 1 texture { T[0] } pigment { P[1] } finish { F[0] } }
#debug "ok\n"

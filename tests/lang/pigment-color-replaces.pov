// A colour first in a pigment block makes the pigment that colour, even
// over a pattern (POV-Ray 3.7); after a pattern keyword in the same block
// colours are the pattern's list.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare A = pigment { checker rgb 1 rgb 0 }
#declare B = pigment { A rgb <1, 0, 0> }
#declare C = pigment { B checker rgb <0, 1, 0> rgb <0, 0, 1> }
#declare FA = function { pigment { A } }
#declare FB = function { pigment { B } }
#declare FC = function { pigment { C } }
#declare P = array[2] {<0.5, 0.5, 0.5>, <1.5, 0.5, 0.5>}
#for (I, 0, 1)
#debug concat(vstr(3, FA(P[I].x, P[I].y, P[I].z), ",", 0, 3), " ", vstr(3, FB(P[I].x, P[I].y, P[I].z), ",", 0, 3), " ", vstr(3, FC(P[I].x, P[I].y, P[I].z), ",", 0, 3), "\n")
#end

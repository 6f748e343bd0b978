// expect: 3:50: this hexagon list holds pigments: a color cannot be mixed in
#version 3.7;
#declare P = pigment { hexagon pigment { rgb 1 } color rgb 0.5 }

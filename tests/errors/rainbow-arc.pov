// expect: 3:63: a rainbow's arc_angle must be from 0 to 360 degrees, not 400
#version 3.7;
rainbow { direction z angle 42 width 5 distance 100 arc_angle 400 color_map { [0 rgb 1] [1 rgb 0] } }

// expect: 3:81: a rainbow's falloff_angle (120) must not be larger than its arc_angle (100)
#version 3.7;
rainbow { direction z angle 42 width 5 distance 100 arc_angle 100 falloff_angle 120 color_map { [0 rgb 1] [1 rgb 0] } }

// expect: 3:1: a rainbow needs a direction other than <0, 0, 0>
#version 3.7;
rainbow { angle 42 width 5 distance 100 color_map { [0 rgb 1] [1 rgb 0] } }

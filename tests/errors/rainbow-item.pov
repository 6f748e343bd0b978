// expect: 3:53: expected a rainbow item or '}', found 'pigment'
#version 3.7;
rainbow { direction z angle 42 width 5 distance 100 pigment { rgb 1 } }

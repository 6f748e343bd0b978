// expect: 587:3: #error: Circle_Text: the text "abcdefghij" (2.061502 wide) is longer than a circle of radius 0.300000
// expect-file: shapes.inc
// shapes.inc's Circle_Text stops with an error when the text is longer than
// the circle (2 pi Radius), as POV-Ray's does (measured: 25 letters 5.398
// wide stop at radius 0.8590 and pass at 0.8592).
#version 3.7;
#include "shapes.inc"
#declare T = Circle_Text("timrom.ttf", "abcdefghij", 0.5, 0, 0.2, 0.3, 0, Align_Center, 90);

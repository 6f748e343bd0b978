// expect: 6:3: this cubic_spline sub-prism does not close: its start (the point after this one) must come again, then an end control point
// (POV-Ray stops with "Uncategorized error" here.) The first sub-prism is
// closed; the second starts at <2,0> (control) <1,1> and never returns.
#version 3.7;
prism { cubic_spline 0, 1, 12, <1,-1>, <0,0>, <6,0>, <6,8>, <0,0>, <-1,1>,
  <2,0>, <1,1>, <5,1>, <5,7>, <1,6>, <0,2> }

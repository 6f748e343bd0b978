// A polygon needs three points (POV-Ray: "Polygon needs at least three points").
// expect: 3:11: a polygon needs at least 3 points, found 2
polygon { 2, <0,0>, <1,0> }

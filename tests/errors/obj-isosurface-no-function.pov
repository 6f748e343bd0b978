// An isosurface begins with its function (POV-Ray: "Expected 'function', contained_by found instead").
// expect: 3:14: expected 'function' (an isosurface begins with its function), found 'contained_by'
isosurface { contained_by { box { -1, 1 } } }

// The container is a box or a sphere (POV-Ray: "No matching } in 'contained_by', cone found instead").
// expect: 3:44: expected box or sphere (the only containers of an isosurface), found 'cone'
isosurface { function { x } contained_by { cone { 0, 1, 1, 0 } } }

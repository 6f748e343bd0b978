// Isosurface items come before the object modifiers (POV-Ray: "No matching } in 'isosurface', threshold found instead").
// expect: 3:41: expected an object modifier or '}', found 'threshold'
isosurface { function { x } translate x threshold 0.5 }

// Blob components come before the object modifiers, as in POV-Ray.
// expect: 3:45: expected an object modifier or '}', found 'sphere'
blob { sphere { 0, 1, 1 } pigment { rgb 1 } sphere { x, 1, 1 } }

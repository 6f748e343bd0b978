// expect: 7:30: undefined identifier 'k'; did you mean 'K'?
// POV-Ray reads an array index in a function body when the function is
// defined: a parameter of the function is not known there (POV-Ray 3.7:
// "undeclared identifier 'k'").
#declare F = array[2] { function { x }, function { y } }
#declare K = 1;
#declare H = function(k) { F[k](1, 2, 3) }

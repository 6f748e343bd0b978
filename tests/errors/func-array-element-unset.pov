// expect: 5:25: element of array 'F' used before it was given a value
// POV-Ray: "Attempt to access uninitialized array element."
#declare F = array[2]
#declare F[0] = function { x }
#declare G = function { F[1](x, y, z) }

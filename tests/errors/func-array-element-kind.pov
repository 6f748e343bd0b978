// expect: 5:25: the element of array 'V' is a vector; a function body can use floats and functions only
// An array element in a function body must be a float or a function, as
// any identifier there.
#declare V = array[2] { <1, 2, 3>, <4, 5, 6> }
#declare H = function { V[1] + x }

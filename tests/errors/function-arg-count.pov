// expect: 3:14: this function takes 2 arguments, not 1
#declare F = function(a, b) { a + b }
#declare X = F(1);

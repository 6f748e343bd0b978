// checks passing user functions and splines to macros (the manual's examples)
#version 3.7;
#macro Foo(Bar, X)
  #declare Y = Bar(X);
  #declare Z = Bar(Y);
#end
#declare FUNC = function(n) { n + 2 }
Foo(FUNC, 1)
#debug concat(str(Y, 5, 5), "\n")
#debug concat(str(Z, 5, 5), "\n")
#macro Foo2(Bar, Val)
  #declare Y = Bar(Val).y;
#end
#declare myspline = spline { 1, <4,5> 3, <5,5> 5, <6,5> }
Foo2(myspline, 2)
#debug concat(str(Y, 5, 5), "\n")

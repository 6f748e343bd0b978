// checks macro parameters of every kind: float, vector, colour, string, array, object, function
#version 3.7;
#macro Describe(F, V, C, S, A, O, Fn)
  #debug concat(str(F, 0, 1), " ", vstr(3, V, ",", 0, 1), " ", vstr(5, C, ",", 0, 1), " ", S, "\n")
  #debug concat(str(dimension_size(A, 1), 0, 0), " ", vstr(3, max_extent(O), ",", 0, 1), " ", str(Fn(2, 3, 4), 0, 1), "\n")
#end
#declare Arr = array[4];
#declare Obj = sphere { 0, 2 }
#declare Fun = function { x + y * z }
Describe(1.5, <1,2,3>, rgbt <0.5,0.5,0.5,0.5>, "str", Arr, Obj, Fun)
Describe(2, x, rgb 1, concat("a", "b"), array[2], box { 0, 1 }, function { x })

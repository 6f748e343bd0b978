// obj-args-no-commas.pov: object arguments without commas. A '<' after a
// complete value starts the next vector (comparisons bind only inside
// parentheses), so these are the objects their commas would make.
#macro Ext(M)
  #debug concat(vstr(3, min_extent(M), ",", 0, 3), " / ", vstr(3, max_extent(M), ",", 0, 3), "\n")
#end
Ext(box { <0,0,0> <1,2,3> })
Ext(cylinder { <0,0,0> <0,1,0> 0.5 })
Ext(cone { <0,0,0> 1 <0,2,0> 0.5 })
Ext(triangle { <0.3,0.1,-0.3> <2.2,0.1,0.2> <1.4,1.7,0.8> })
Ext(sphere { <1,2,3> 0.5 })
#declare A = 1;
Ext(sphere { <A,A,A> (A < 2) + 1 })

// checks vector literals whose components are not separated by commas
#version 3.7;
#declare V = <1 2 3>;
#declare W = < -1 0 0 >;
#declare U = <1 -2, 3>;
#declare A = 2;
#declare X = <A -1 A>;
#debug concat(vstr(3,V,",",0,1), " ", vstr(3,W,",",0,1), " ", vstr(3,U,",",0,1), " ", vstr(3,X,",",0,1), "\n")
#declare I = 0;
#while (I < 3)
  #declare Y = <I I+1 -I>;
  #debug concat(vstr(3,Y,",",0,1), "\n")
  #declare I = I + 1;
#end

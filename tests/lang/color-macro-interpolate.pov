// checks one macro interpolating floats, vectors and colours alike
#version 3.7;
#macro Interpolate(T,T1,T2,P1,P2)
  (P1+(T1+T/(T2-T1))*(P2-P1))
#end
#declare I = 5;
#debug concat(vstr(3, Interpolate(I,0,15,<2,3,4>,<9,8,7>), ",", 0, 6), "\n")
#debug concat(str(Interpolate(I,0,15,3.0,5.5), 0, 6), "\n")
#declare C = Interpolate(I,0,15,rgb<1,1,0>,rgb<0,1,1>);
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare Value = Interpolate(I,0,15,3.0,5.5)*15;
#debug concat(str(Value, 0, 6), "\n")

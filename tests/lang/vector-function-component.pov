// checks spline and transform functions called inside a float function:
// the call needs a component (.x .y .z .u .v .red .green .blue .filter
// .transmit .gray), and the function gives the spline's or the point's value
#version 3.7;
#declare S = function { spline { linear_spline 0, <1,2,3> 1, <3,4,5> } }
#declare S5 = function { spline { linear_spline 0, <1,2,3,4,5> 1, <3,4,5,6,7> } }
#declare T = function { transform { translate <1,2,3> scale 2 } }
#declare A = function { S(x).x + 10*S(x).y + 100*S(x).z }
#declare B = function { S(x).u + S(x).v + S(x).red + S(x).green + S(x).blue }
#declare C = function { S5(x).t + S5(x).filter + S5(x).transmit + S5(x).gray }
#declare D = function(a, b, c) { T(a, b, c).x * 100 + T(a, b, c).y * 10 + T(c, b, a).z }
#declare E = function { S(x * 0.5).gray + T(x, y, z).gray }
#debug concat(str(A(0.3, 0, 0), 0, 6), "\n")
#debug concat(str(B(0.7, 0, 0), 0, 6), "\n")
#debug concat(str(C(0.25, 0, 0), 0, 6), "\n")
#debug concat(str(D(1, 2, 3), 0, 6), "\n")
#debug concat(str(E(0.5, 1, -2), 0, 6), "\n")

// checks calling user functions in float expressions, vectors, loops and conditions
#version 3.7;
#declare F = function(a) { a * a - 2 }
#debug concat(str(F(3) + F(4) * 2, 0, 6), "\n")
#debug concat(vstr(3, <F(1), F(2), F(3)>, ",", 0, 6), "\n")
#declare I = 0;
#while (F(I) < 20) #declare I = I + 1; #end
#debug concat("first I with F(I)>=20: ", str(I, 0, 0), "\n")
#if (F(2) = 2) #debug "F(2)=2\n" #end

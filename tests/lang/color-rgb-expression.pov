// checks rgb/rgbf/rgbt applied to vector expressions and identifiers
#version 3.7;
#declare H = <1,2,3>;
#declare I = rgb H;
#debug concat(vstr(5, I, ",", 0, 6), "\n")
#declare J = rgb H/4;
#debug concat(vstr(5, J, ",", 0, 6), "\n")
#declare K = rgbf <H.x, H.y, H.z, 0.5>/2;
#debug concat(vstr(5, K, ",", 0, 6), "\n")
#declare Foo = 0.5; #declare Bar = 1.5; #declare Bob = 0.9;
#declare Weird = rgb <Foo*2,Bar-1,Bob/3>;
#debug concat(vstr(5, Weird, ",", 0, 6), "\n")

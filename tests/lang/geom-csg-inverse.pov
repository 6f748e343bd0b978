// trace() through CSG with inverted unions: POV-Ray inverts a union into the intersection of its
// inverted children (no inner surfaces), and a twice-inverted union into a merge; a difference
// inverts its subtracted children. Non-inverted unions keep their inner surfaces.
#version 3.7;
#macro T(N, O, P, D)
  #local Nr = <0,0,0>;
  #local H = trace(O, P, D, Nr);
  #debug concat(N, " ", vstr(3, H, ",", 0, 6), "  ", vstr(3, Nr, ",", 0, 6), "\n")
#end
#declare U = union { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} }
T("d-plane", difference { sphere {0,1.5} object { U } plane {-y,0} }, <0.01,5,0.03>, -y)
T("d-noplane", difference { sphere {0,1.5} object { U } }, <0.01,5,0.03>, -y)
T("i-inv", intersection { sphere {0,1.5} object { U inverse } }, <0.01,5,0.03>, -y)
T("i-inv-plane", intersection { sphere {0,1.5} object { U inverse } plane {y,0} }, <0.01,5,0.03>, -y)
T("i-noinv-plane", intersection { sphere {0,1.5} object { U } plane {y,0} }, <0.01,5,0.03>, -y)
T("i-noinv-plane-up", intersection { sphere {0,1.5} object { U } plane {y,0} }, <0.01,-5,0.03>, y)
T("i-noinv", intersection { sphere {0,1.5} object { U } }, <0.01,5,0.03>, -y)
T("i-noinv-up", intersection { sphere {0,1.5} object { U } }, <0.01,-5,0.03>, y)
T("m-plane", difference { sphere {0,1.5} merge { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} } plane {-y,0} }, <0.01,5,0.03>, -y)
T("u-inv-alone", object { U inverse }, <0.01,5,0.03>, -y)
T("u-alone", object { U }, <0.01,5,0.03>, -y)
#declare O = <0,0.01,0.02>;
T("u-alone-in", object { U }, O, x)
T("u-inv-in", object { U inverse }, O, x)
T("u-invinv-in", object { object { U inverse } inverse }, O, x)
T("i-u", intersection { object { U } sphere {0,1.5} }, O, x)
T("i-uinvinv", intersection { object { object { U inverse } inverse } sphere {0,1.5} }, O, x)
T("d-ufirst", difference { object { U } sphere {<5,0,0>,0.1} }, O, x)
T("d-dd", difference { sphere{0,1.5} difference { sphere{0,3} object { U inverse } } }, O, x)
T("i-uinv-out", intersection { object { U inverse } sphere {0,1.5} }, <0.01,-0.3,0.02>, -x)
T("u-in-u", difference { sphere{0,1.5} union { union { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} } sphere{<0,0.5,0>,0.9} } plane {-y,0} }, <0.01,5,0.03>, -y)
T("i-inv-i", difference { sphere{0,1.5} intersection { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} } plane {-y,0} }, <0.01,5,0.03>, -y)
T("u-in-m", difference { sphere{0,1.5} merge { union { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} } sphere{<0,-2,0>,0.1} } plane {-y,0} }, <0.01,5,0.03>, -y)
T("u-in-i-inv", intersection { sphere{0,1.5} intersection { object { U } sphere{0,3} inverse } plane {y,0} }, <0.01,5,0.03>, -y)
T("u-in-d", difference { sphere{0,1.5} difference { object { U } sphere{<0,-3,0>,0.1} } plane {-y,0} }, <0.01,5,0.03>, -y)
T("u-inv-last", union { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} inverse }, <0,0.01,0.02>, x)
T("u-clip", difference { sphere {0,1.5} union { sphere {<-0.5,0,0>,0.9} sphere {<0.5,0,0>,0.9} clipped_by { plane { z, 1 } } } plane {-y,0} }, <0.01,5,0.03>, -y)
T("u-tr", difference { sphere {0,1.5} object { U rotate 90*y translate 0.01*x } plane {-y,0} }, <0.02,5,0.03>, -y)

// checks vector comparisons reduced to floats with dot items and vlength inside #if
#version 3.7;
#declare A = <1, 2, 3>;
#declare B = <1, 2, 3.0000000000001>;
#if (vlength(A - B) = 0) #debug "A equals B within tolerance\n" #end
#declare C = (A = B);
#if (C.x & C.y & C.z) #debug "all components equal\n" #end

// checks rebuilding a vector with one component changed via dot items
#version 3.7;
#declare V = <1, 2, 3>;
#declare V = <V.x, 20, V.z>;
#debug concat(vstr(3, V, ",", 0, 0), "\n")
#declare V = V * <1, 0, 1> + y * 5;
#debug concat(vstr(3, V, ",", 0, 0), "\n")

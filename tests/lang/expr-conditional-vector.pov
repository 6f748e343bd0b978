// checks the conditional operator choosing between vectors
#version 3.7;
#declare Foo = 1;
#declare Bar = 2;
#declare V = (Foo < Bar ? <1,2,3> : <5,6,7>);
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#declare W = (Foo > Bar ? <1,2,3> : <5,6,7>);
#debug concat(vstr(3, W, ",", 0, 6), "\n")
#declare U = (1 ? x : y) + z;
#debug concat(vstr(3, U, ",", 0, 6), "\n")

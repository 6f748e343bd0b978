// checks that relational operators on vectors work component by component
#version 3.7;
#declare R = (<1,2,3> = <3,2,1>);
#debug concat(vstr(3, R, ",", 0, 6), "\n")
#declare S = (<1,2,3> < <2,2,2>);
#debug concat(vstr(3, S, ",", 0, 6), "\n")
#declare T2 = (<1,2,3> != 2);
#debug concat(vstr(3, T2, ",", 0, 6), "\n")
#declare U2 = (<1,5,3> >= <1,2,4>);
#debug concat(vstr(3, U2, ",", 0, 6), "\n")

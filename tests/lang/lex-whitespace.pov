// checks tokens without separating spaces, spaces after '#', and tabs/newlines inside expressions
#version 3.7;
#declare B=3;#declare C=4;#debug concat(str(B+C,0,0),"\n")
#   debug "space after hash\n"
#declare D =
	1
	+
	2	*	3
	;
#debug concat(str(D, 0, 0), "\n")
#declare V=<1,2,3>;#debug concat(vstr(3,V*2,",",0,0),"\n")

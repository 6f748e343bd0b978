// checks built-in identifiers used inside expressions, vectors and conditions
#version 3.7;
#declare V = <pi, true, off>;
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#declare Ang = pi/2;
#debug concat(str(sin(Ang), 0, 6), "\n")
#debug concat(str(((yes & on) | off), 0, 6), "\n")
#debug concat(str(clock*360 + 10, 0, 6), "\n")
#debug concat(str(!false, 0, 6), "\n")

// checks macro invocations mixed into float and vector expressions
#version 3.7;
#macro One() 1 #end
#macro Vec() <1, 2, 3> #end
#debug concat(str(One() + One() * 3, 0, 6), "\n")
#debug concat(vstr(3, Vec() + One(), ",", 0, 6), "\n")
#debug concat(vstr(3, <One(), One() + 1, 3 * One()>, ",", 0, 6), "\n")
#debug concat(str(-One(), 0, 6), "\n")

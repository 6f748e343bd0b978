// checks strlen() and the sign of strcmp()
#version 3.7;
#debug concat(str(strlen(""), 0, 0), " ", str(strlen("a"), 0, 0), " ", str(strlen("Hello There!"), 0, 0), " ", str(strlen("tab\there"), 0, 0), "\n")
#macro Sgn(F) (F < 0 ? -1 : (F > 0 ? 1 : 0)) #end
#debug concat(str(Sgn(strcmp("abc", "abc")), 0, 0), " ", str(Sgn(strcmp("abc", "abd")), 0, 0), " ", str(Sgn(strcmp("b", "a")), 0, 0), "\n")
#debug concat(str(Sgn(strcmp("ab", "abc")), 0, 0), " ", str(Sgn(strcmp("B", "a")), 0, 0), " ", str(Sgn(strcmp("", "")), 0, 0), "\n")

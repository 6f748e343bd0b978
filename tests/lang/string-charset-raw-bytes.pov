// Bytes of the scene file that are not ASCII, in a string read under
// charset ascii (the default): each becomes a space when the string is read,
// so asc() gives 32 and a later charset utf8 does not bring them back.
// The expected output is what POV-Ray 3.7 prints.
#version 3.7;
#declare S = "aébÃ©c";
#debug concat(str(strlen(S),0,0), " ", str(asc(substr(S,2,1)),0,0), " ", str(asc(substr(S,4,1)),0,0), " ", str(asc(substr(S,5,1)),0,0), "\n")
#debug concat("[", S, "]\n")
#macro M(X) #debug concat(str(asc(X),0,0), "\n") #end
M("ö")
#declare T = concat("ä", "x")
#debug concat(str(asc(T),0,0), " ", str(strcmp(T, " x"),0,0), "\n")
global_settings { charset utf8 }
#debug concat(str(strlen(S),0,0), " ", str(asc(substr(S,2,1)),0,0), "\n")
#debug concat(str(asc("\u00e9"),0,0), "\n")

// string-utf8-read.pov: under charset utf8 POV-Ray decodes a string's UTF-8
// when it is read: each 2- or 3-byte sequence is one character (its code
// from asc), a 4-byte one is U+FFFD; strlen, substr and strcmp count them.
#version 3.7;
global_settings { charset utf8 }
#declare S = "aéb€c";
#debug concat(str(strlen(S),0,0), " ", str(asc(substr(S,2,1)),0,0), " ", str(asc(substr(S,4,1)),0,0), " ", substr(S,3,1), "\n")
#declare T = "x😀y";
#debug concat(str(strlen(T),0,0), " ", str(asc(substr(T,2,1)),0,0), " ", substr(T,3,1), "\n")
#debug concat(str(strcmp("é", "è"),0,0), " ", str(strlen(concat("αβ", "Ж")),0,0), " ", str(asc("Ж"),0,0), "\n")
#declare E = "\u00e9";
#debug concat(str(strcmp(E, "é"),0,0), "\n")

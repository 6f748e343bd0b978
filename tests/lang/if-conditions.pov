// checks #if conditions built from logical, relational and string operations
#version 3.7;
#declare A = 3; #declare B = 4;
#if ((A < B) & (B < 5)) #debug "both\n" #end
#if ((A > B) | (B = 4)) #debug "either\n" #end
#if (!(A = B)) #debug "not equal\n" #end
#if ("abc" = "abc") #debug "strings equal\n" #end
#if (strlen("four") = B) #debug "strlen ok\n" #end
#if (A - 3) #debug "wrong\n" #else #debug "zero is false\n" #end
#if (1e-11) #debug "wrong\n" #else #debug "tiny is false\n" #end

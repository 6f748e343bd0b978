// checks string equality inside #if, and its equivalence with strcmp
#version 3.7;
#declare S1 = "red";
#declare S2 = concat("re", "d");
#if (S1 = S2) #debug "equal\n" #else #debug "different\n" #end
#if (strcmp(S1, S2) = 0) #debug "strcmp equal\n" #end
#if (S1 != "blue") #debug "not blue\n" #end

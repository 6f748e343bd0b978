// checks that POV-Ray's #debug stream wraps lines longer than 80 columns (at a space if it can)
#version 3.7;
#declare S = "";
#for (I, 1, 100) #declare S = concat(S, chr(48 + mod(I, 10))); #end
#debug concat(substr(S, 1, 80), "\n")
#debug concat(substr(S, 1, 81), "\n")
#debug concat(S, "\n")
#debug "aaaa bbbb cccc dddd eeee ffff gggg hhhh iiii jjjj kkkk llll mmmm nnnn oooo pppp qqqq rrrr\n"
#debug "aaaa bbbb cccc dddd eeee ffff gggg hhhh iiii jjjj kkkk llll mmmm nnnn oooo pppp"
#debug " qqqq rrrr\n"

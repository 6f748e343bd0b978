// checks line comments, block comments, nested block comments and comments inside expressions
#version 3.7;
/* outer /* nested */ still comment */
#debug "after nested comment\n"
#declare A = 1 /* inline */ + // line comment
  2;
#debug concat(str(A, 0, 0), "\n")
// #debug "commented out\n"
/*
#debug "also commented out\n"
*/
#debug "end\n"

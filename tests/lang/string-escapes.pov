// checks string escape sequences \t \\ \" \' and their lengths
#version 3.7;
#debug "a\tb\\c\"d\'e\n"
#debug "Joe said \"Hello\" as he walked in.\n"
#debug "This is a backslash \\ and this is two \\\\\n"
#debug concat(str(strlen("\t"), 0, 0), str(strlen("\\"), 0, 0), str(strlen("\""), 0, 0), str(strlen("\n"), 0, 0), str(strlen("\'"), 0, 0), "\n")
#debug concat(str(asc("\t"), 0, 0), " ", str(asc("\n"), 0, 0), " ", str(asc("\\"), 0, 0), " ", str(asc("\""), 0, 0), " ", str(asc("\'"), 0, 0), "\n")

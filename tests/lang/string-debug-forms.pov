// checks #debug with a literal, an identifier, a function result and several directives in a row
#version 3.7;
#declare Msg = "from identifier\n";
#debug "literal\n"
#debug Msg
#debug concat("from ", "concat", "\n")
#debug str(42, 0, 0) #debug "\n"
#debug chr(65) #debug chr(10)
#debug "no newline yet..." #debug " now\n"

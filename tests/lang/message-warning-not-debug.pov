// checks that #warning text goes to the warning stream, not into the #debug output
#version 3.7;
#debug "debug 1\n"
#warning "this is a warning and must not appear in the debug output\n"
#debug "debug 2\n"
#warning concat("computed warning ", str(42, 0, 0), "\n")
#debug "debug 3\n"

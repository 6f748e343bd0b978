// expect: 3:8: unterminated string: the file ends before its closing '"'
// A string may span lines, so the one below runs to the end of the file.
#debug "no end
#declare A = 1;

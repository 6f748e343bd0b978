// expect: 2:8: unterminated string: no closing '"' on this line
#debug "no end


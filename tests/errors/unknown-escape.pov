// expect: 2:11: unknown escape sequence '\q' in string
#debug "a \q b"

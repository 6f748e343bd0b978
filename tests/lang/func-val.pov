// checks val() on numeric strings of various forms
#version 3.7;
#debug concat(str(val("123.45"), 0, 6), "\n")
#debug concat(str(val("-0.5"), 0, 6), "\n")
#debug concat(str(val("1e3"), 0, 6), "\n")
#debug concat(str(val("  42"), 0, 6), "\n")
#debug concat(str(val("7"), 0, 6), "\n")
#debug concat(str(val(".25"), 0, 6), "\n")
#debug concat(str(val("12abc"), 0, 6), "\n")
#debug concat(str(val("abc"), 0, 6), "\n")
#debug concat(str(val(str(3.75, 0, 2)) * 2, 0, 6), "\n")

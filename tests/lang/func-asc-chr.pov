// checks asc() and chr() and their round trip
#version 3.7;
#debug concat(str(asc("ABC"), 0, 0), " ", str(asc("a"), 0, 0), " ", str(asc(" "), 0, 0), " ", str(asc("0"), 0, 0), " ", str(asc("~"), 0, 0), "\n")
#debug concat(chr(70), chr(111), chr(111), chr(33), "\n")
#debug concat(chr(asc("Q")), " ", str(asc(chr(90)), 0, 0), "\n")
#for (I, 65, 74) #debug chr(I) #end
#debug "\n"

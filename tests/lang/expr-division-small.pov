// checks division results printed with many digits
#version 3.7;
#debug concat(str(1/7, 0, 10), "\n")
#debug concat(str(22/7, 0, 10), "\n")
#debug concat(str(1/1024, 0, 10), "\n")
#debug concat(str(1e6/3, 0, 4), "\n")
#debug concat(str(-2/3, 0, 10), "\n")

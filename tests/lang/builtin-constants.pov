// checks the built-in float constants pi true false yes no on off
#version 3.7;
#debug concat("pi=", str(pi, 0, 15), "\n")
#debug concat("true=", str(true, 0, 6), " false=", str(false, 0, 6), "\n")
#debug concat("yes=", str(yes, 0, 6), " no=", str(no, 0, 6), "\n")
#debug concat("on=", str(on, 0, 6), " off=", str(off, 0, 6), "\n")
#debug concat("2*pi=", str(2*pi, 0, 10), "\n")
#debug concat(str(true + yes + on, 0, 6), "\n")

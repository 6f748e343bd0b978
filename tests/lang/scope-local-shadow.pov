// checks that a macro's #local hides a global of the same name (even of another type) only inside the macro
#version 3.7;
#declare B = rgb <1, 2, 3>;
#macro M()
  #local B = "a string now";
  #debug concat("in macro: ", B, "\n")
#end
M()
#debug concat("after: ", vstr(5, B, ",", 0, 0), "\n")

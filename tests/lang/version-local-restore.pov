// checks saving version in a local, switching, and restoring with #version Identifier
#version 3.7;
#macro Old_Stuff()
  #local Temp_Vers = version;
  #version 3.1;
  #debug concat("inside: ", str(version, 0, 2), "\n")
  #version Temp_Vers;
#end
Old_Stuff()
#debug concat("after: ", str(version, 0, 2), "\n")

// checks string identifiers without semicolons and reassignment
#version 3.7;
#declare Font_Name = "ariel.ttf"
#declare Inc_File = "myfile.inc"
#local L = "local string";
#declare Font_Name = strupr(Font_Name)
#debug concat(Font_Name, " ", Inc_File, " ", L, "\n")
#declare E = "";
#debug concat("[", E, "] ", str(strlen(E), 0, 0), "\n")

// checks file_exists() on present and absent files, relative to the scene folder
#version 3.7;
#debug concat(str(file_exists("func-file-exists.pov"), 0, 0), "\n")
#debug concat(str(file_exists("inc/helper.inc"), 0, 0), "\n")
#debug concat(str(file_exists("no-such-file-here.txt"), 0, 0), "\n")
#debug concat(str(file_exists(input_file_name), 0, 0), "\n")
#debug concat(str(file_exists(concat("inc/", "helper", ".inc")), 0, 0), "\n")

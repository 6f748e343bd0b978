// checks the input_file_name string identifier
#version 3.7;
#debug concat("input_file_name=", input_file_name, "\n")
#debug concat(str(strlen(input_file_name), 0, 0), "\n")

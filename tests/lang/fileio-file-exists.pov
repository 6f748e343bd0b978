// checks file_exists() before and after a file is written
#version 3.7;
#debug concat(str(file_exists("fileio-file-exists.tmp"), 0, 0), "\n")
#fopen F "fileio-file-exists.tmp" write
#write (F, "1\n")
#fclose F
#debug concat(str(file_exists("fileio-file-exists.tmp"), 0, 0), "\n")

// expect: 3:9: the file 'F' was opened for reading
#fopen F "write-to-read-file.pov" read
#write (F, "x")

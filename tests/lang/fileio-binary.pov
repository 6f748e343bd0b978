// checks #write with binary word types: the bytes are written and then included as text
#version 3.7;
#fopen F "fileio-binary.tmp" write
#write (F, "#debug \"")
#write (F, uint8 72, 105)
#write (F, uint16be 8257)
#write (F, uint16le 16961)
#write (F, sint8 67, uint8 33)
#write (F, "\\n\"\n")
#fclose F
#include "fileio-binary.tmp"

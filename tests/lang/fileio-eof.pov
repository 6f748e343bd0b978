// checks reading until end of file: the handle becomes undefined at EOF
#version 3.7;
#fopen F "fileio-eof.tmp" write
#for (I, 1, 5)
  #write (F, I * 1.5, ",\n")
#end
#fclose F
#fopen F "fileio-eof.tmp" read
#declare Count = 0;
#declare Total = 0;
#while (defined(F))
  #read (F, V)
  #if (defined(F))
    #declare Count = Count + 1;
    #declare Total = Total + V;
  #end
#end
#debug concat("count=", str(Count, 0, 0), " total=", str(Total, 0, 6), "\n")

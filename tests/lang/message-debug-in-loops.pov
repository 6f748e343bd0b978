// checks #debug text assembled over several directives into one line
#version 3.7;
#for (I, 1, 10)
  #debug str(I, 0, 0)
  #if (I < 10) #debug "," #end
#end
#debug "\n"
#debug "" #debug "" #debug "empty strings print nothing\n"

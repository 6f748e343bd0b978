// checks a #switch where nothing matches and there is no #else
#version 3.7;
#switch (10)
  #case (1) #debug "one\n" #break
  #range (2, 5) #debug "2-5\n" #break
#end
#debug "nothing matched\n"
#switch (3)
  #range (5, 1) #debug "reversed range matched\n" #break
  #else #debug "reversed range never matches\n"
#end

// checks that directives between #switch and the first #case are executed (POV-Ray 3.7 runs them)
#version 3.7;
#declare Seen = 0;
#switch (2)
  #debug "before first case\n"
  #declare Seen = 1;
  #case (1)
    #debug "one\n"
  #break
  #case (2)
    #debug "two\n"
  #break
#end
#debug concat("Seen=", str(Seen, 0, 0), "\n")
#switch (99)
  #debug "before first case, no clause matches\n"
  #case (1)
    #debug "one\n"
#end

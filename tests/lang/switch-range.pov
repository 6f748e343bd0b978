// checks #range clauses (inclusive at both ends)
#version 3.7;
#macro Grade(N)
  #switch (N)
    #range (0, 49.999) #debug "fail\n" #break
    #range (50, 74) #debug "pass\n" #break
    #range (75, 100) #debug "distinction\n" #break
    #else #debug "out of range\n"
  #end
#end
Grade(0) Grade(49.999) Grade(50) Grade(74) Grade(74.5) Grade(75) Grade(100) Grade(101) Grade(-1)

// checks that #case compares with a small tolerance (values within 1e-10 are equal)
#version 3.7;
#switch (0.1 + 0.2)
  #case (0.3) #debug "0.1+0.2 matched 0.3\n" #break
  #else #debug "no match\n"
#end
#switch (1 + 1e-12)
  #case (1) #debug "1+1e-12 matched 1\n" #break
  #else #debug "no match\n"
#end
#switch (1 + 1e-6)
  #case (1) #debug "matched\n" #break
  #else #debug "1+1e-6 did not match 1\n"
#end

// checks #switch and #case with computed expressions and identifiers
#version 3.7;
#declare TEST_1 = 2;
#declare TEST_2 = 4;
#declare VALUE = 8/2;
#switch (VALUE)
  #case (TEST_1) #debug "TEST_1\n" #break
  #case (TEST_2) #debug "TEST_2\n" #break
  #range (TEST_1 * 2, TEST_2 * 2) #debug "range\n" #break
#end
#switch (mod(17, 5))
  #case (sqrt(4)) #debug "mod 17 5 is 2\n" #break
#end

// checks fall-through: after a true clause without #break, the next clauses run without being tested (like C)
#version 3.7;
#macro F(N)
  #debug concat("N=", str(N, 0, 0), ":")
  #switch (N)
    #case (1)
      #debug " case1"
    #case (2)
      #debug " case2"
    #case (3)
      #debug " case3"
      #break
    #case (4)
      #debug " case4"
  #end
  #debug "\n"
#end
F(1) F(2) F(3) F(4) F(5)

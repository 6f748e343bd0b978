// checks fall-through from a true clause into following #range clauses: their bodies run WITHOUT re-testing
#version 3.7;
#macro F(N)
  #debug concat("N=", str(N, 0, 0), ":")
  #switch (N)
    #case (5)
      #debug " five"
    #range (1, 3)
      #debug " one-to-three"
    #range (4, 6)
      #debug " four-to-six"
      #break
    #else
      #debug " else"
  #end
  #debug "\n"
#end
F(2) F(5) F(4) F(9)

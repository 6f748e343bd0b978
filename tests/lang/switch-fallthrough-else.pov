// checks that #else runs when the clause before it was true but had no #break
#version 3.7;
#macro F(N)
  #debug concat("N=", str(N, 0, 0), ":")
  #switch (N)
    #case (1)
      #debug " one"
    #case (2)
      #debug " two"
      #break
    #case (3)
      #debug " three"
    #else
      #debug " else"
  #end
  #debug "\n"
#end
F(1) F(2) F(3) F(4)

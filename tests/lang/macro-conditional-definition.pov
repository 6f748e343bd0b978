// checks defining a macro inside #if: only the chosen definition exists
#version 3.7;
#declare Fancy = 0;
#if (Fancy)
  #macro Style() "fancy" #end
#else
  #macro Style() "plain" #end
#end
#debug concat(Style(), "\n")
